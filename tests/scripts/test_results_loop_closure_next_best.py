"""python/results_loop_closure_next_best.py (docs/results.md section loop-closure-next-best) on hand-made run
folders (no data, no runs): the branches.csv counts, the paired up / down counts (higher `da_accuracy_real` is
better, lower ATE for the simulations, undefined figures left out), and the table's cells per family kind.

Usage: test_results_loop_closure_next_best.py
"""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_loop_closure_next_best as section  # noqa: E402
from run_folder_case import RunFolderCase  # noqa: E402


class LoopClosureNextBestSection(RunFolderCase):
    def test_kept_counts_read_branches_csv(self):
        folder = self.folder("a", {}, ["3,19,10.5,12.0,,as-is", "30,46,10.0,9.0,8.5,next-best",
                                       "60,76,10.0,9.0,9.5,apart"])
        self.assertEqual(section.kept_counts(folder), (3, 2, 1))
        self.assertEqual(section.kept_counts(self.folder("b", {})), (0, 0, 0))  # no split: no file

    def test_paired_changes(self):
        before = [{"da_accuracy_real": 0.5}, {"da_accuracy_real": 0.6}, {"da_accuracy_real": None},
                  {"da_accuracy_real": 0.7}]
        after = [{"da_accuracy_real": 0.55}, {"da_accuracy_real": 0.6}, {"da_accuracy_real": 0.9},
                 {"da_accuracy_real": 0.65}]
        self.assertEqual(section.paired_changes("mrclam", before, after), "1 / 1")
        # Simulations: a lower ATE is better.
        self.assertEqual(section.paired_changes("simulation", [{"ate_rmse": 2.0}, {"ate_rmse": 1.0}],
                                                [{"ate_rmse": 1.5}, {"ate_rmse": 1.2}]), "1 / 1")

    def test_the_table_has_a_row_per_family(self):
        folders = {}
        families = {"MRCLAM": ("mrclam", [("r1", "r1.jsonl"), ("r2", "r2.jsonl")]),
                    "KITTI 00": ("simulation", [("seed 1", "s1.jsonl"), ("seed 2", "s2.jsonl")])}
        values = {("MRCLAM", "r1"): (0.4, 0.5), ("MRCLAM", "r2"): (0.6, 0.6)}
        for (family, name), (two, third) in values.items():
            folders[(family, name, 0)] = self.folder(f"{name}-0", {"da_accuracy_real": two})
            folders[(family, name, 1)] = self.folder(f"{name}-1", {"da_accuracy_real": third, "time_s": 2.0},
                                                     ["5,21,1.0,2.0,0.5,next-best"])
        ates = {"seed 1": (3.0, 1.5, 1.0), "seed 2": (1.0, 1.0, 1.0)}  # two branches, three, known
        for name, (two, third, known) in ates.items():
            folders[("KITTI 00", name, 0)] = self.folder(f"{name}-0", {"ate_rmse": two})
            folders[("KITTI 00", name, 1)] = self.folder(f"{name}-1", {"ate_rmse": third})
            folders[("KITTI 00", name, "known")] = self.folder(f"{name}-k", {"ate_rmse": known})
        lines = section.comparison_table(families, folders)
        self.assertEqual(len(lines), 4)
        mrclam = [c.strip() for c in lines[2].strip("|").split("|")]
        self.assertEqual(mrclam, ["MRCLAM", "0.500", "0.550", "1 / 0", "2.0 / 4.0", "2 / 2 / 2"])
        simulation = [c.strip() for c in lines[3].strip("|").split("|")]
        self.assertEqual(simulation, ["KITTI 00", "1 of 2, 2.000", "2 of 2, 1.250", "1 / 0", "2.0 / 2.0",
                                      "0 / 0 / 0"])


if __name__ == "__main__":
    unittest.main()
