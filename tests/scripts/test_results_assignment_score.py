"""python/results_assignment_score.py (docs/results.md section assignment-score) on hand-made run folders (no data,
no runs): the decisions table's means per family, independent → joint, and the splits cell.

Usage: test_results_assignment_score.py
"""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_assignment_score as section  # noqa: E402
from run_folder_case import RunFolderCase  # noqa: E402


class AssignmentScoreSection(RunFolderCase):
    def test_the_decisions_table_has_the_means_of_each_family(self):
        families = {"MRCLAM": ("mrclam", [("r1", "r1.jsonl"), ("r2", "r2.jsonl")])}
        folders = {}
        for name, before, after in [("r1", 0.9, 0.95), ("r2", 0.8, 0.85)]:
            folders[("MRCLAM", name, 2)] = self.folder(f"{name}-2", {
                "decision_accuracy_real": before, "decision_clutter_rejected": None,
                "decisions_resighting_elsewhere": 10, "decisions_resighting_unassigned": 4,
                "decisions_first_sighting_forced": 1})
            folders[("MRCLAM", name, 3)] = self.folder(f"{name}-3", {
                "decision_accuracy_real": after, "decision_clutter_rejected": None,
                "decisions_resighting_elsewhere": 6, "decisions_resighting_unassigned": 3,
                "decisions_first_sighting_forced": 1})
        lines = section.decisions_table(families, folders)
        self.assertEqual(len(lines), 3)
        self.assertEqual(lines[2], "| MRCLAM | 0.850 → 0.900 | – → – | 10.0 → 6.0 | 4.0 → 3.0 | 1.0 → 1.0 |")

    def test_the_splits_cell_sums_branches_csv_rows(self):
        a = self.folder("a", {}, ["3,19,10.5,12.0,,as-is", "30,46,10.0,9.0,8.5,next-best"])
        b = self.folder("b", {})  # no split: no file
        c = self.folder("c", {}, ["3,19,10.5,12.0,,apart"])
        self.assertEqual(section.split_counts([[a, b], [c, b]]), "2 / 1")


if __name__ == "__main__":
    unittest.main()
