"""python/results_association.py (docs/results.md section association): the KITTI target's "≤ ml" comparison, in
which two ATEs within a micrometre are equal (runs with the same associations differ by round-off only). Needs no
data and no semslam binary."""
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


if __name__ == "__main__":
    unittest.main()
