"""python/paired_runs.py on hand-made run folders: runs paired by folder name, a metric undefined on either side or a
folder on one side only left out, the prefix filter, and the summary's mean, t and counts."""
import json
import math
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import paired_runs  # noqa: E402


def write(root, name, **metrics):
    os.makedirs(os.path.join(root, name))
    with open(os.path.join(root, name, "metrics.json"), "w") as out:
        json.dump(metrics, out)


class PairedRuns(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.base = os.path.join(self.scratch.name, "base")
        self.cand = os.path.join(self.scratch.name, "cand")
        write(self.base, "m1", ate_rmse=1.0, da_accuracy_real=0.5)
        write(self.cand, "m1", ate_rmse=1.5, da_accuracy_real=0.4)
        write(self.base, "m2", ate_rmse=2.0, da_accuracy_real=None)
        write(self.cand, "m2", ate_rmse=1.0, da_accuracy_real=0.9)
        write(self.base, "t1", ate_rmse=1.0, da_accuracy_real=0.7)
        write(self.cand, "t1", ate_rmse=1.25, da_accuracy_real=0.7)
        write(self.cand, "only-here", ate_rmse=9.0, da_accuracy_real=0.1)

    def tearDown(self):
        self.scratch.cleanup()

    def test_runs_pair_by_name_and_skip_what_either_side_lacks(self):
        self.assertEqual(paired_runs.differences(self.base, self.cand, "ate_rmse"),
                         {"m1": 0.5, "m2": -1.0, "t1": 0.25})
        da = paired_runs.differences(self.base, self.cand, "da_accuracy_real")
        self.assertEqual(sorted(da), ["m1", "t1"])
        self.assertAlmostEqual(da["m1"], -0.1)
        self.assertEqual(paired_runs.differences(self.base, self.cand, "ate_rmse", ["m"]), {"m1": 0.5, "m2": -1.0})

    def test_the_settings_the_pairs_differ_in_are_named(self):
        settings = {"schema": "semslam.settings/1", "version": "0.1.0", "method": "mm-nh",
                    "association": {"gate": 0.9, "unassigned_rate_weight": None}}
        for root, name, weight, version in ((self.base, "m1", None, "0.1.0"), (self.cand, "m1", 100.0, "0.2.0"),
                                            (self.base, "m2", None, "0.1.0"), (self.cand, "m2", 100.0, "0.1.0")):
            written = json.loads(json.dumps(settings))
            written["association"]["unassigned_rate_weight"] = weight
            written["version"] = version  # the release that wrote a folder is not a setting
            if root == self.cand and name == "m2":
                written["association"]["gate"] = 0.95
                del written["method"]
            with open(os.path.join(root, name, "settings.json"), "w") as out:
                json.dump(written, out)
        found, recorded, unrecorded = paired_runs.setting_differences(self.base, self.cand)
        self.assertEqual(recorded, 2)
        self.assertEqual(found, {("association.unassigned_rate_weight", "null", "100.0"): 2,
                                 ("association.gate", "0.9", "0.95"): 1, ("method", '"mm-nh"', None): 1})
        self.assertEqual(unrecorded, 1)  # t1: no settings.json ("only-here" has no pair)
        self.assertEqual(paired_runs.setting_differences(self.base, self.cand, ["t"]), ({}, 0, 1))

    def test_the_summary_is_the_paired_mean_t_and_counts(self):
        s = paired_runs.summary([0.5, -1.0, 0.25])
        self.assertAlmostEqual(s["mean"], -0.25 / 3)
        sd = math.sqrt(((0.5 + 0.25 / 3) ** 2 + (-1.0 + 0.25 / 3) ** 2 + (0.25 + 0.25 / 3) ** 2) / 2)
        self.assertAlmostEqual(s["sd"], sd)
        self.assertAlmostEqual(s["t"], (-0.25 / 3) / (sd / math.sqrt(3)))
        self.assertEqual((s["higher"], s["lower"], s["count"]), (2, 1, 3))
        self.assertLessEqual(s["ci_low"], s["mean"])
        self.assertGreaterEqual(s["ci_high"], s["mean"])
        self.assertEqual(paired_runs.summary([])["count"], 0)


if __name__ == "__main__":
    unittest.main()
