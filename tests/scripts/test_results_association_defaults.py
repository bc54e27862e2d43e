"""python/results_association_defaults.py (docs/results.md section association-defaults) on hand-made metrics (no
data, no runs): the section skipped without logs, MRCLAM's mean and paired difference from the defaults' runs of
the same logs, the KITTI simulations counted against known association's ATE, and the tracking means.

Usage: test_results_association_defaults.py
"""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import results_association_defaults as section  # noqa: E402


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


class AssociationDefaultsSection(unittest.TestCase):
    def test_without_logs_the_section_says_it_is_skipped(self):
        with tempfile.TemporaryDirectory() as empty:
            lines = section.association_defaults_section("semslam", empty, empty)
        self.assertTrue(lines[0].startswith("## The unassigned rule's defaults"))
        self.assertIn("section skipped", lines[2])

    def test_a_flag_without_a_value_is_not_given(self):
        flags = section.setting_flags(section.DEFAULTS)
        self.assertNotIn("--unassigned-rate-weight", flags)
        self.assertEqual(flags[flags.index("--unassigned-rate") + 1], "1")
        weighted = section.setting_flags(dict(section.DEFAULTS, **{"--unassigned-rate-weight": "100"}))
        self.assertEqual(weighted[weighted.index("--unassigned-rate-weight") + 1], "100")
        self.assertEqual(len(weighted), len(flags) + 2)

    def test_the_table(self):
        settings = [dict(section.DEFAULTS), dict(section.DEFAULTS, **{"--patience": "5"})]

        def mrclam(values):
            return {f"r{i}": {"da_accuracy_real": v, "ate_rmse": 1.0 + i, "clutter_rejected": 0.5}
                    for i, v in enumerate(values)}

        results = {
            (0, "MRCLAM"): mrclam([0.5, 0.6, 0.7]), (1, "MRCLAM"): mrclam([0.6, 0.6, 0.5]),
            (0, "Lost in the Woods"): {"litw": {"da_accuracy_real": 0.99, "ate_rmse": 0.027}},
            (1, "Lost in the Woods"): {"litw": {"da_accuracy_real": 0.98, "ate_rmse": 0.03}},
            ("known", "KITTI"): {"a": {"ate_rmse": 1.0}, "b": {"ate_rmse": 2.0}},
            # both within 2 × known (b at the bound), then a outside it
            (0, "KITTI"): {"a": {"ate_rmse": 1.5}, "b": {"ate_rmse": 4.0}},
            (1, "KITTI"): {"a": {"ate_rmse": 2.5}, "b": {"ate_rmse": 3.0}},
            (0, "KITTI tracking 1 Hz"): {"t0": {"da_accuracy_real": 0.8, "clutter_rejected_moving": 0.9,
                                                "clutter_rejected_false_positive": 0.7},
                                         "t6": {"da_accuracy_real": None, "clutter_rejected_moving": 0.5,
                                                "clutter_rejected_false_positive": 0.5}},
            (1, "KITTI tracking 1 Hz"): {"t0": {"da_accuracy_real": 0.6, "clutter_rejected_moving": 1.0,
                                                "clutter_rejected_false_positive": 0.6},
                                         "t6": {"da_accuracy_real": None, "clutter_rejected_moving": 0.5,
                                                "clutter_rejected_false_positive": 0.5}},
        }
        lines = section.defaults_table(settings, results)
        header = cells(lines[2])
        self.assertEqual(header[1], "MRCLAM (3 runs): mean `da_accuracy_real`")
        self.assertEqual(header[6], "KITTI 00 / 07 (2 logs): ATE ≤ 2 × known's, mean ATE [m]")
        self.assertEqual(header[7], "KITTI tracking 1 Hz ×5 (2 seq.)")
        defaults, patience = cells(lines[4]), cells(lines[5])
        self.assertEqual(defaults, ["defaults (μ 1 constant, M 2, Δt 1 s, no viewpoint rule, N 10)", "0.600", "–",
                                    "2.000", "0.50", "0.990 / 0.027", "2 of 2, 2.750", "0.800 (1) / 0.700 / 0.600"])
        self.assertEqual(patience[0], "--patience 5")
        self.assertEqual(patience[1], "0.567")
        # differences +0.1, 0, −0.2: mean −0.033, one run higher and one lower
        self.assertTrue(patience[2].startswith("-0.033 ["), patience[2])
        self.assertTrue(patience[2].endswith("], 1 / 1"), patience[2])
        self.assertEqual(patience[5:], ["0.980 / 0.030", "1 of 2, 2.750", "0.600 (1) / 0.750 / 0.550"])


if __name__ == "__main__":
    unittest.main()
