"""python/plot_hybrid.py on a small seeded study of the CLI: the per-layout and pooled comparison, the NEES subsets
and the Fig. 5 analog.

Usage: test_plot_hybrid.py SEMSLAM_BINARY
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "python", "plot_hybrid.py")
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

    def test_fig5_writes_a_figure(self):
        out = os.path.join(self.scratch.name, "fig5.png")
        subprocess.run([sys.executable, "-B", SCRIPT, "fig5", self.study, "--out", out], check=True,
                       capture_output=True)
        self.assertGreater(os.path.getsize(out), 10000)


if __name__ == "__main__":
    unittest.main()
