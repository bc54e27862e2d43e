"""python/plot_hybrid.py on a small seeded study of the CLI: the per-layout and pooled comparison, the NEES subsets
and the Fig. 5 analog; python/hypotheses.py and the Fig. 4 analog on two runs of one aliased track.

Usage: test_plot_hybrid.py SEMSLAM_BINARY
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

PYTHON = os.path.join(os.path.dirname(__file__), "..", "..", "python")
SCRIPT = os.path.join(PYTHON, "plot_hybrid.py")
sys.path.insert(0, PYTHON)
import hypotheses  # noqa: E402
SEMSLAM = sys.argv.pop(1) if len(sys.argv) > 1 else "semslam"


class PlotHybrid(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = tempfile.TemporaryDirectory()
        cls.study = os.path.join(cls.scratch.name, "study")
        subprocess.run([SEMSLAM, "study", "hybrid", "--layouts", "2", "--tracks", "4", "--steps", "4", "--alpha",
                        "0,0.5", "--samples", "60", "--seed", "3", "--quiet", "--out", cls.study], check=True,
                       capture_output=True)

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def test_analyze_compares_per_layout_and_pooled(self):
        done = subprocess.run([sys.executable, "-B", SCRIPT, "analyze", self.study, "--alpha", "0.5"], check=True,
                              capture_output=True, text=True)
        result = json.loads(done.stdout)
        self.assertEqual(result["layouts"], 2)
        self.assertEqual(result["tracks"], 8)
        for metric in ("entropy", "det_cov", "err_wmax", "err_wavg"):
            paired = result["paired"][metric]
            self.assertEqual(sorted(paired["per_layout"]), ["0", "1"])
            self.assertLessEqual(paired["ci_low"], paired["mean_difference"])
            self.assertLessEqual(paired["mean_difference"], paired["ci_high"])
            self.assertGreaterEqual(paired["layouts_separating"], 0)
            self.assertLessEqual(paired["layouts_separating"], 2)
            # The pooled mean is the mean of the per-layout means weighed by their tracks (4 each here).
            layouts = paired["per_layout"].values()
            self.assertAlmostEqual(paired["mean_difference"], sum(l["mean"] for l in layouts) / 2, places=12)
        for model in ("classifier", "geometric"):
            nees = result["nees"][model]
            self.assertEqual(nees["heaviest"]["count"], 8)
            self.assertEqual(nees["heaviest_correct"]["count"] + nees["heaviest_wrong"]["count"], 8)
        self.assertIn("entropy_slope", result)

    def test_runs_are_counted_once(self):
        # runs.csv repeats each track's geometric run at both alphas; the per-run sums read it once, as timings.csv
        # lists it once: 2 layouts x 4 tracks x (2 classifier runs + 1 geometric run).
        sys.path.insert(0, PYTHON)
        import plot_hybrid  # noqa: E402
        rows = plot_hybrid.read_runs(self.study)
        self.assertEqual(len(rows), 32)
        runs = plot_hybrid.runs_of(rows)
        self.assertEqual(len(runs), 24)
        self.assertEqual(len(plot_hybrid.read_timings(self.study)), 24)
        self.assertEqual(sum(1 for r in runs if r["model"] == "geometric"), 8)

    def test_fig5_writes_a_figure(self):
        out = os.path.join(self.scratch.name, "fig5.png")
        subprocess.run([sys.executable, "-B", SCRIPT, "fig5", self.study, "--out", out], check=True,
                       capture_output=True)
        self.assertGreater(os.path.getsize(out), 10000)


class Hypotheses(unittest.TestCase):
    """hypotheses.jsonl stores each history once (beta_k and an ancestor index); following the ancestors of the
    heaviest final component gives the history the run folder's associations.csv lists."""

    @classmethod
    def setUpClass(cls):
        cls.scratch = tempfile.TemporaryDirectory()
        log = os.path.join(cls.scratch.name, "track.jsonl")
        subprocess.run([SEMSLAM, "simulate", "aliased2d", "--steps", "8", "--seed", "2", "--out", log], check=True,
                       capture_output=True)
        cls.runs = {}
        for method in ("hybrid", "hybrid-geometric"):
            out = os.path.join(cls.scratch.name, method)
            subprocess.run([SEMSLAM, "run", "--method", method, "--in", log, "--out", out, "--samples", "200",
                            "--quiet"], check=True, capture_output=True)
            cls.runs[method] = out

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def test_the_heaviest_history_is_the_run_folders(self):
        for out in self.runs.values():
            lines = hypotheses.read(os.path.join(out, "hypotheses.jsonl"))
            last = len(lines) - 1
            weights = [c["weight"] for c in lines[last]["components"]]
            heaviest = weights.index(max(weights))
            history = hypotheses.history(lines, last, heaviest)
            listed = {}
            with open(os.path.join(out, "associations.csv")) as f:
                for row in csv.DictReader(f):
                    listed.setdefault(int(row["step"]), []).append(
                        -1 if row["landmark"] in ("", "null") else int(row["landmark"]))
            self.assertEqual(len(history), len(lines))
            for k, beta in enumerate(history):
                self.assertEqual(beta, listed.get(k, []), f"step {k}")
            marginal = hypotheses.association_marginal(lines, last)
            self.assertAlmostEqual(sum(w for _, w in marginal), 1.0, places=9)
            self.assertIn(history, [h for h, _ in marginal])

    def test_fig4_writes_a_figure(self):
        out = os.path.join(self.scratch.name, "fig4.png")
        subprocess.run([sys.executable, "-B", SCRIPT, "fig4", self.runs["hybrid"], self.runs["hybrid-geometric"],
                        "--steps", "1,4,8", "--out", out], check=True, capture_output=True)
        self.assertGreater(os.path.getsize(out), 10000)


if __name__ == "__main__":
    unittest.main()
