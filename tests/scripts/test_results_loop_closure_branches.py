"""python/results_loop_closure_branches.py (docs/results.md section loop-closure-branches) on a small seeded
version: two 30-step semantic simulations (seeds 4 and 5; seed 4's first re-sightings anchor, so a split opens),
windows 0 and 8. Checks the run folders (W = 0 is the default run: the same trajectory bit for bit as a run without
the option, and no branches.csv), the split counts against branches.csv, the table's rows and cells, the summary the
figure draws (against the runs' metrics), and that plot_loop_closure_branches.py draws it (Debian's matplotlib).

Usage: test_results_loop_closure_branches.py SEMSLAM_BINARY
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import results_loop_closure_branches as section  # noqa: E402
from results_commands import read_metrics  # noqa: E402

PLOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "plot_loop_closure_branches.py")

SEMSLAM = None
WINDOWS = [0, 8]


class LoopClosureBranchesSection(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = tempfile.TemporaryDirectory()
        logs = []
        for seed in (4, 5):
            log = os.path.join(cls.scratch.name, f"sim{seed}.jsonl")
            subprocess.run([SEMSLAM, "simulate", "semantic", "--steps", "30", "--seed", str(seed), "--out", log],
                           check=True, capture_output=True)
            logs.append((f"seed {seed}", log))
        cls.families = {"Simulation": ("simulation", logs)}
        cls.folders = section.run_sweep(SEMSLAM, cls.families, cls.scratch.name, WINDOWS)
        cls.lines = section.sweep_tables(cls.families, cls.folders, WINDOWS)

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def test_no_window_is_the_default_run(self):
        _, log = self.families["Simulation"][1][0]
        plain = os.path.join(self.scratch.name, "plain")
        subprocess.run([SEMSLAM, "run", "--quiet", "--method", "mm-nh", "--in", log, "--out", plain,
                        "--no-covariances"], check=True, capture_output=True)
        with open(os.path.join(plain, "trajectory.tum")) as a, \
                open(os.path.join(self.folders[("Simulation", "seed 4", 0)], "trajectory.tum")) as b:
            self.assertEqual(a.read(), b.read())
        self.assertEqual(section.branch_splits(self.folders[("Simulation", "seed 4", 0)]), (0, 0))

    def test_a_window_splits_and_the_counts_come_from_branches_csv(self):
        folder = self.folders[("Simulation", "seed 4", 8)]
        with open(os.path.join(folder, "branches.csv")) as f:
            rows = f.read().splitlines()
        self.assertEqual(rows[0], "opened_at,closed_after,score_as_is,score_apart,score_next_best,kept")
        splits, apart = section.branch_splits(folder)
        self.assertEqual(splits, len(rows) - 1)
        self.assertGreaterEqual(splits, 1)
        self.assertEqual(apart, sum(1 for row in rows[1:] if row.split(",")[-1] == "apart"))

    def test_the_tables_have_a_row_per_window_and_the_known_baseline(self):
        self.assertEqual(self.lines[0], "| W | Simulation | Simulation splits |")
        first = self.lines[:self.lines.index("")]
        rows = {line.split(" | ")[0]: line for line in first if line.startswith("| ")}
        for window in WINDOWS:
            cells = rows[f"| {window}"].strip("| ").split(" | ")
            self.assertRegex(cells[1], r"^[0-2] of 2, [0-9.]+$")
            self.assertRegex(cells[2], r"^[0-9]+ / [0-9]+$")
        self.assertEqual(rows["| 0"].strip("| ").split(" | ")[2], "0 / 0")
        self.assertNotEqual(rows["| 8"].strip("| ").split(" | ")[2], "0 / 0")
        per_log = self.lines[self.lines.index("") + 1:]
        self.assertEqual(per_log[0], "Simulation, ATE [m] per log:")
        labels = [line.split(" | ")[0] for line in per_log if line.startswith("| ") and not line.startswith("| W")]
        self.assertEqual(labels, ["| 0", "| 8", "| `known`"])
        for line in per_log[4:]:
            self.assertEqual(len(line.strip("| ").split(" | ")), 3, line)  # the window and one ATE per log


    def test_the_summary_is_the_runs_ates_over_known_and_its_figure_is_drawn(self):
        summary = section.sweep_summary(self.families, self.folders, WINDOWS)
        self.assertEqual(summary["windows"], WINDOWS)
        self.assertEqual(summary["real"], {})
        ratios = summary["simulations"]["Simulation"]
        self.assertEqual(len(ratios), 2)
        for (name, _), per_window in zip(self.families["Simulation"][1], ratios):
            known = read_metrics(self.folders[("Simulation", name, "known")])["ate_rmse"]
            for window, ratio in zip(WINDOWS, per_window):
                ate = read_metrics(self.folders[("Simulation", name, window)])["ate_rmse"]
                self.assertAlmostEqual(ratio, ate / known, places=12)
        path = os.path.join(self.scratch.name, "summary.json")
        with open(path, "w") as f:
            json.dump(dict(summary, real={"Real": [0.5, 0.6]}), f)
        figure = os.path.join(self.scratch.name, "sweep.png")
        subprocess.run([sys.executable, PLOT, path, "--out", figure], check=True, capture_output=True)
        with open(figure, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    SEMSLAM = sys.argv.pop(1)
    unittest.main()
