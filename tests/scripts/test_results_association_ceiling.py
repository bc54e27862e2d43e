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

    def test_the_csv_is_what_the_plot_reads(self):
        import subprocess
        import tempfile
        with tempfile.TemporaryDirectory() as folder:
            table = os.path.join(folder, "ceiling.csv")
            section.write_csv(self.results(), table)
            with open(table) as handle:
                lines = handle.read().splitlines()
            self.assertEqual(lines[0], "robot,draw,scale,seed,da_accuracy_real")
            self.assertEqual(lines[1], "1,,0,1,0.91")  # the unmoved ceiling first
            self.assertEqual(len(lines), 1 + len(section.ROBOTS) * (1 + len(section.COLUMNS) * len(section.SEEDS)))
            plot = os.path.join(os.path.dirname(section.__file__), "plot_association_ceiling.py")
            try:
                import matplotlib  # noqa: F401
            except ImportError:
                self.skipTest("python3-matplotlib is not installed: the plot is not drawn")
            figure = os.path.join(folder, "ceiling.png")
            subprocess.run([sys.executable, plot, table, figure], check=True)
            self.assertGreater(os.path.getsize(figure), 1000)
            sys.path.insert(0, os.path.dirname(plot))
            import plot_association_ceiling
            curves = plot_association_ceiling.read_curves(table)
            self.assertEqual(sorted(curves), ["independent", "joint"])
            # robot 1's joint curve: the unmoved ceiling at s = 0, then the three joint scales' seed means
            self.assertEqual([s for s, _ in curves["joint"][1]], [0.0, 0.5, 1.0, 2.0])
            self.assertAlmostEqual(curves["joint"][1][0][1], 0.91)
            self.assertAlmostEqual(curves["joint"][1][2][1], 0.62)


if __name__ == "__main__":
    unittest.main()


class TrueHistoryTable(unittest.TestCase):
    def runs(self):
        decided, own = {}, {}
        for robot in section.ROBOTS:
            for seed in section.LABEL_SEEDS:
                decided[(robot, seed)] = {"decision_accuracy_real": 0.9 + 0.01 * seed,
                                          "decision_clutter_rejected": 0.95,
                                          "decisions_resighting_elsewhere": robot,
                                          "decisions_resighting_unassigned": 2,
                                          "decisions_first_sighting_forced": seed}
                own[(robot, seed)] = 0.5 + 0.1 * robot
        return decided, own

    def test_cells_are_means_with_ranges_and_error_counts_are_summed_over_the_seeds(self):
        decided, own = self.runs()
        lines = section.true_history_table(decided, own)
        self.assertEqual(len(lines), 2 + len(section.ROBOTS) + 1)
        row = lines[3].split(" | ")  # robot 2
        self.assertEqual(row[0], "| 2")
        self.assertEqual(row[1], "0.920 (0.910-0.930)")
        self.assertEqual(row[2], "0.700 (0.700-0.700)")
        self.assertEqual(row[3], "6")  # elsewhere: robot 2 on each of 3 seeds
        self.assertEqual(row[4], "6")  # unassigned: 2 on each
        self.assertEqual(row[5], "6")  # forced: 1 + 2 + 3
        self.assertEqual(row[6], "0.950 (0.950-0.950) |")
        mean = lines[-1].split(" | ")
        self.assertEqual(mean[1], "0.920")
        self.assertEqual(mean[2], "0.800")  # (0.6 + 0.7 + 0.8 + 0.9 + 1.0) / 5

    def test_a_robot_without_runs_is_a_dash(self):
        decided, own = self.runs()
        for seed in section.LABEL_SEEDS:
            del decided[(4, seed)]
            del own[(4, seed)]
        lines = section.true_history_table(decided, own)
        self.assertTrue(lines[5].startswith("| 4 | – | – | – | – | – | – |"))
