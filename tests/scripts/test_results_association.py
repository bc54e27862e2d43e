"""python/results_association.py (docs/results.md section association): the KITTI target's "≤ ml" comparison, in
which two ATEs within a micrometre are equal (runs with the same associations differ by round-off only), and the
target's rows and counts. Needs no data and no semslam binary."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import results_association as section  # noqa: E402


class AtMost(unittest.TestCase):
    def test_round_off_is_a_tie_and_a_tie_is_at_most(self):
        self.assertTrue(section.at_most(3.6994305 + 6.5e-11, 3.6994305))  # KITTI 07 seed 3, mm-nh against ml
        self.assertTrue(section.at_most(1.3110022 + 1.9e-9, 1.3110022))   # seed 4
        self.assertTrue(section.at_most(1.0, 1.0))
        self.assertTrue(section.at_most(0.9, 1.0))

    def test_a_difference_a_method_makes_is_not_a_tie(self):
        self.assertFalse(section.at_most(1.1418339, 1.1396761))  # KITTI 00 seed 1: 2.2 mm above
        self.assertFalse(section.at_most(1.0 + 2e-6, 1.0))
        self.assertTrue(section.at_most(1.0 + 0.5e-6, 1.0))


class KittiTargetRows(unittest.TestCase):
    @staticmethod
    def metrics(ate, da=0.9, time=1.0):
        return {"ate_rmse": ate, "da_accuracy_real": da, "time_s": time}

    def test_each_bound_is_counted_and_both_make_the_target(self):
        m = self.metrics
        rows = [("00", 1, m(1.0), m(1.5), m(1.5)),        # both (mm-nh equal to ml)
                ("00", 2, m(1.0), m(1.5), m(2.5)),        # neither: above 2 × known and above ml
                ("07", 1, m(1.0), m(3.0), m(1.9)),        # both; ml itself beyond 2 × known
                ("07", 2, m(2.0), m(1.0), m(3.0))]        # within 2 × known, above ml
        lines = section.kitti_target_rows(rows, "sequence")
        self.assertEqual(len(lines), 6)
        self.assertEqual(lines[0], "| 00 | 1 | 1.000 | 1.500 | 1.500 | +0.0000 | 0.900 | 0.900 | 1.0 | yes | yes | yes |")
        self.assertTrue(lines[1].endswith("| no | no | no |"))
        self.assertTrue(lines[3].endswith("| yes | no | no |"))
        self.assertEqual(lines[5], "mm-nh within 2 × known-DA's ATE on 3 of 4 logs (ml on 3), at most ml's on 2 (1 of "
                                   "them equal to it to a micrometre), both (the target) on 2. Where mm-nh's ATE is "
                                   "above ml's, it is so by 1.0000 to 2.0000 m (at most 200.0% of ml's); on 1 of "
                                   "those 2 ml's ATE is below known association's own.")


if __name__ == "__main__":
    unittest.main()
