"""python/results_loop_closure_open_splits.py (docs/results.md section loop-closure-open-splits) on hand-made run
folders (no data, no runs): the section skipped without logs, the listed splits per variant, the table's row per
family, and the simulations' ATE per seed beside `known` association's.

Usage: test_results_loop_closure_open_splits.py
"""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_loop_closure_open_splits as section  # noqa: E402
from run_folder_case import RunFolderCase  # noqa: E402


class LoopClosureOpenSplitsSection(RunFolderCase):
    def test_without_logs_the_section_says_it_is_skipped(self):
        empty = os.path.join(self.scratch.name, "no-data")
        os.makedirs(empty)
        lines = section.loop_closure_open_splits_section("semslam", empty, self.scratch.name, " ".join)
        self.assertEqual(lines[0], "## Splits within splits at ambiguous loop closures (issue 10)")
        self.assertIn(section.NO_LOGS, lines)

    def test_listed_splits_per_variant(self):
        one = [self.folder("a0", {}, ["3,19,1.0,2.0,,as-is"]), self.folder("b0", {})]
        two = [self.folder("a1", {}, ["3,19,1.0,2.0,,as-is", "4,20,1.0,0.5,,apart"]),
               self.folder("b1", {}, ["7,23,1.0,2.0,3.0,as-is"])]
        self.assertEqual(section.listed_splits([one, two]), "1 / 3")

    def test_the_table_and_the_simulations_ate_per_seed(self):
        families = {"MRCLAM": ("mrclam", [("r1", "r1.jsonl"), ("r2", "r2.jsonl")]),
                    "KITTI 00": ("simulation", [("seed 1", "s1.jsonl"), ("seed 2", "s2.jsonl")])}
        folders = {}
        for name, (one, two) in {"r1": (0.4, 0.6), "r2": (0.6, 0.5)}.items():
            folders[("MRCLAM", name, 0)] = self.folder(f"{name}-0", {"da_accuracy_real": one}, ["1,17,1,2,,as-is"])
            folders[("MRCLAM", name, 1)] = self.folder(f"{name}-1", {"da_accuracy_real": two, "time_s": 3.0},
                                                       ["1,17,1,2,,as-is", "2,18,1,2,,as-is"])
        for name, (one, two, known) in {"seed 1": (5.5, 1.5, 1.4), "seed 2": (1.0, 1.0, 1.0)}.items():
            folders[("KITTI 00", name, 0)] = self.folder(f"{name}-0", {"ate_rmse": one})
            folders[("KITTI 00", name, 1)] = self.folder(f"{name}-1", {"ate_rmse": two})
            folders[("KITTI 00", name, "known")] = self.folder(f"{name}-k", {"ate_rmse": known})
        lines = section.comparison_table(families, folders, section.VARIANTS, times_header="one / two open",
                                         counts_header="splits listed", counts=section.listed_splits)
        self.assertIn("time [s] (sum, one / two open)", lines[0])
        mrclam = [c.strip() for c in lines[2].strip("|").split("|")]
        self.assertEqual(mrclam, ["MRCLAM", "0.500", "0.550", "1 / 1", "2.0 / 6.0", "2 / 4"])
        simulation = [c.strip() for c in lines[3].strip("|").split("|")]
        self.assertEqual(simulation, ["KITTI 00", "1 of 2, 3.250", "2 of 2, 1.250", "1 / 0", "2.0 / 2.0", "0 / 0"])
        rows = section.simulation_ate_rows(families, folders)
        (one, _), (two, _) = section.VARIANTS
        self.assertIn(f"| {one} | 5.500 | 1.000 |", rows)
        self.assertIn(f"| {two} | 1.500 | 1.000 |", rows)
        self.assertIn("| `known` | 1.400 | 1.000 |", rows)


if __name__ == "__main__":
    unittest.main()
