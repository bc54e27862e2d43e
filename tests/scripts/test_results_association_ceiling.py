"""python/results_association_ceiling.py (docs/results.md section association-ceiling) on hand-made figures: each
cell is the mean over the seeds with its range, the columns are in their order, a missing run is a dash, and the
mean row averages the robots' means. Needs no data and no semslam binary."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import results_association_ceiling as section  # noqa: E402


class CeilingTable(unittest.TestCase):
    def results(self):
        results = {}
        for robot in section.ROBOTS:
            results[(robot, None, 0.0, 1)] = 0.9 + 0.01 * robot
            for c, (draw, scale) in enumerate(section.COLUMNS):
                for seed in section.SEEDS:
                    results[(robot, draw, scale, seed)] = 0.5 + 0.1 * c + 0.01 * seed
        return results

    def test_cells_are_the_mean_over_seeds_with_the_range(self):
        lines = section.ceiling_table(self.results())
        self.assertEqual(lines[0], "| robot | unmoved (s = 0) | joint, s = 0.5 | joint, s = 1 | joint, s = 2 | "
                                   "independent, s = 0.5 | independent, s = 1 |")
        row = lines[2].split(" | ")
        self.assertEqual(row[0], "| 1")
        self.assertEqual(row[1], "0.910")               # one unmoved run: no range
        self.assertEqual(row[2], "0.520 (0.510-0.530)")  # column 0: 0.5 + 0.01 × seed
        self.assertEqual(row[6], "0.920 (0.910-0.930) |")

    def test_the_mean_row_averages_the_robots_and_a_missing_run_is_a_dash(self):
        results = self.results()
        for seed in section.SEEDS:
            del results[(3, "joint", 2.0, seed)]
        lines = section.ceiling_table(results)
        self.assertIn("| 3 | 0.930 | 0.520 (0.510-0.530) | 0.620 (0.610-0.630) | – |", lines[4])
        mean = lines[-1].split(" | ")
        self.assertEqual(mean[0], "| mean")
        self.assertEqual(mean[1], "0.930")  # (0.91 + 0.92 + 0.93 + 0.94 + 0.95) / 5
        self.assertEqual(mean[4], "0.720")  # joint s = 2 over the four robots that have it


if __name__ == "__main__":
    unittest.main()
