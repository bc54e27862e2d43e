"""python/results_backends.py (docs/results.md section back-ends, issue 10's back-end target) on hand-made metrics:
the bound max(10 %, 0.02 m) at both of its regimes, the rows' pairing of the two back ends, the speed-up, and the
summary's counts. Needs no data and no semslam binary."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import results_backends as section  # noqa: E402


def metrics(ate, da, seconds):
    return {"ate_rmse": ate, "da_accuracy_real": da, "time_s": seconds}


class Backends(unittest.TestCase):
    def test_the_bound_is_ten_percent_or_two_centimetres_whichever_is_larger(self):
        self.assertTrue(section.within(1.09, 1.0))    # 10 % of 1 m
        self.assertFalse(section.within(1.11, 1.0))
        self.assertTrue(section.within(0.919, 0.9))   # the same on the other side
        self.assertTrue(section.within(0.119, 0.1))   # 2 cm, above 10 % of 0.1 m
        self.assertFalse(section.within(0.121, 0.1))

    def test_worse_is_the_upper_side_of_the_bound_only(self):
        self.assertTrue(section.worse(1.11, 1.0))
        self.assertFalse(section.worse(1.09, 1.0))
        self.assertFalse(section.worse(0.5, 1.0))     # far below: outside the bound, but not worse
        self.assertTrue(section.worse(0.121, 0.1))
        self.assertFalse(section.worse(0.119, 0.1))

    def test_rows_pair_the_back_ends_and_count_the_target(self):
        results = {
            ("A", "ml", "incremental"): metrics(1.0, 0.9, 0.5),
            ("A", "ml", "batch"): metrics(1.05, 0.8, 25.0),       # within, 50 ×
            ("A", "mm-nh", "incremental"): metrics(2.0, None, 1.0),
            ("A", "mm-nh", "batch"): metrics(1.0, None, 5.0),     # not within, 5 ×
            ("B", "ml", "incremental"): metrics(0.10, 1.0, 0.2),
            ("B", "ml", "batch"): metrics(0.115, 1.0, 2.0),       # within by the 2 cm, 10 ×
            ("B", "mm-nh", "incremental"): metrics(0.5, 1.0, 0.2),
            ("B", "mm-nh", "batch"): metrics(0.9, 1.0, 0.4),      # not within, lower, 2 ×
            ("C", "ml", "incremental"): metrics(0.3, 1.0, 0.1),   # no batch run: no row
        }
        rows = section.backend_rows(results)
        self.assertEqual([(r["log"], r["method"]) for r in rows], [("A", "ml"), ("A", "mm-nh"), ("B", "ml"),
                                                                       ("B", "mm-nh")])
        self.assertEqual([r["within"] for r in rows], [True, False, True, False])
        self.assertEqual([r["worse"] for r in rows], [False, True, False, False])
        self.assertEqual([r["speedup"] for r in rows], [50.0, 5.0, 10.0, 2.0])
        self.assertEqual(rows[0]["da"], (0.9, 0.8))
        self.assertTrue(section.summary(rows).startswith(
            "Within max(10 %, 0.02 m) of the batch back end on 2 of 4 runs, at least 20 × faster on 1, both on 1. "
            "Of the 2 runs outside the bound, the incremental ATE is the higher on 1 and the lower on 1:"))
        lines = section.table(rows)
        self.assertEqual(len(lines), 2 + 4)
        self.assertEqual(lines[3], "| A | mm-nh | 2.000 | 1.000 | no, higher | – / – | 1.00 / 5.00 | 5.0 × |")
        self.assertEqual(lines[5], "| B | mm-nh | 0.500 | 0.900 | no, lower | 1.000 / 1.000 | 0.20 / 0.40 | 2.0 × |")
        for line in lines:
            self.assertEqual(line.count("|"), lines[0].count("|"), line)

    def test_the_switching_table_sets_mm_nhs_switching_run_against_the_same_batch_run(self):
        results = {
            ("A", "ml", "incremental"): metrics(1.0, 0.9, 0.5),
            ("A", "ml", "batch"): metrics(1.05, 0.8, 25.0),
            ("A", "mm-nh", "incremental"): metrics(2.0, 0.5, 1.0),
            ("A", "mm-nh", section.SWITCHING): metrics(1.04, 0.7, 1.5),
            ("A", "mm-nh", "batch"): metrics(1.0, 0.8, 5.0),
        }
        rows = section.backend_rows(section.switching_results(results))
        self.assertEqual([(r["log"], r["method"]) for r in rows], [("A", "mm-nh")])
        self.assertEqual(rows[0]["ate"], (1.04, 1.0))
        self.assertEqual(rows[0]["da"], (0.7, 0.8))
        self.assertTrue(rows[0]["within"])
        self.assertEqual(section.RUN_OPTIONS[section.SWITCHING][-2:], ["--switch-rounds", "5"])


if __name__ == "__main__":
    unittest.main()
