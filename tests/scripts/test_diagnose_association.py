"""python/diagnose_association.py on hand-made run folders: merges, splits, clutter, the chi2 summary and duplicates."""
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "python", "diagnose_association.py")

# Estimate 0 holds true 7 (chi2 0.2, 0.4) and true 8 (chi2 3.0): a merge. True 8 is also on estimate 1: a split.
# Estimate 2 holds clutter only (chi2 1.0, 2.0, 3.0). One clutter detection is on no landmark.
ROWS = """step,detection,landmark,weight,truth,chi2
0,0,0,1,7,0.2
1,0,0,0.9,7,0.4
2,0,0,0.9,8,3.0
3,0,1,1,8,0.5
3,1,1,0.9,8,0.7
4,0,1,0.9,8,0.9
4,1,2,1,not-a-landmark,1.0
5,0,2,0.9,not-a-landmark,2.0
6,0,2,0.9,not-a-landmark,3.0
6,1,null,0.1,not-a-landmark,
"""

# Part 4: true 9 on estimates 3 (3 detections) and 4 (2), a step (9) with a detection on each; true 10 on estimates
# 5 (2) and 6 (1), never at one step; true 11 on estimate 5 once, where it is not the plurality: no duplicate of it.
DUPLICATE_ROWS = """step,detection,landmark,weight,truth,chi2
7,0,3,1,9,0.1
8,0,3,1,9,0.1
9,0,3,1,9,0.1
9,1,4,1,9,0.2
10,0,4,1,9,0.2
11,0,5,1,10,0.1
12,0,5,1,10,0.1
12,1,5,1,11,0.1
13,0,6,1,10,0.1
"""
DUPLICATE_LANDMARKS = """id,x,y,class,p_class
3,0,0,1,0.9
4,3,4,1,0.9
5,1,1,2,0.9
6,1,2,2,0.9
"""


def run(*arguments):
    return subprocess.run([sys.executable, "-B", SCRIPT, *arguments], capture_output=True, text=True)


class DiagnoseAssociation(unittest.TestCase):
    def test_flags_merges_splits_and_summarises_chi2(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "associations.csv"), "w") as f:
                f.write(ROWS)
            result = run(folder)
            self.assertEqual(result.returncode, 0, result.stderr)
            lines = result.stdout.splitlines()
            estimate0 = next(l for l in lines if l.strip().startswith("0  step"))
            self.assertIn("7:2 8:1", estimate0)
            self.assertIn("chi2 1.20", estimate0)  # (0.2 + 0.4 + 3.0) / 3
            self.assertIn("MERGED", estimate0)
            estimate1 = next(l for l in lines if l.strip().startswith("1  step"))
            self.assertNotIn("MERGED", estimate1)
            truth8 = next(l for l in lines if l.strip().startswith("8 "))
            self.assertIn("SPLIT", truth8)
            truth7 = next(l for l in lines if l.strip().startswith("7 "))
            self.assertNotIn("SPLIT", truth7)
            self.assertIn("clutter 4 det., 1 on no landmark", result.stdout)
            # Part 3: estimate 1 is the only one-true-landmark estimate (0.7), estimate 2 the only clutter one (2.0).
            self.assertIn("one true landmark: 1 landmarks, chi2 per detection min 0.70 median 0.70 max 0.70",
                          result.stdout)
            self.assertIn("clutter only: 1 landmarks, chi2 per detection min 2.00 median 2.00 max 2.00",
                          result.stdout)

    def test_lists_duplicates_with_their_distance_and_shared_steps(self):
        with tempfile.TemporaryDirectory() as first, tempfile.TemporaryDirectory() as second:
            for folder in (first, second):
                with open(os.path.join(folder, "associations.csv"), "w") as f:
                    f.write(DUPLICATE_ROWS)
            with open(os.path.join(first, "landmarks.csv"), "w") as f:
                f.write(DUPLICATE_LANDMARKS)
            result = run(first, second, "--duplicates-only")
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertNotIn("1. estimated landmarks", result.stdout)
            lines = [l.strip() for l in result.stdout.splitlines()]
            self.assertIn("9  3 <- 4     2 det.  5.00 m  SEEN AT ONE STEP", lines)
            self.assertIn("10  5 <- 6     1 det.  1.00 m", lines)
            self.assertIn("9  3 <- 4     2 det.  no position  SEEN AT ONE STEP", lines)  # the second folder
            self.assertFalse(any(l.startswith("11 ") for l in lines))
            self.assertIn("duplicates: 4 holding 6 detections; median distance 3.00 m; 2 holding 4 detections seen "
                          "at one step with their main estimate", result.stdout)

    def test_a_bad_row_names_file_and_line(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "associations.csv"), "w") as f:
                f.write("step,detection,landmark,weight,truth,chi2\n0,0,0,1,7,0.2\nx,0,0,1,7,0.2\n")
            result = run(folder)
            self.assertNotEqual(result.returncode, 0)
            self.assertIn("associations.csv:3:", result.stderr)

    def test_a_bad_landmark_row_names_file_and_line(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "associations.csv"), "w") as f:
                f.write(DUPLICATE_ROWS)
            with open(os.path.join(folder, "landmarks.csv"), "w") as f:
                f.write("id,x,y,class,p_class\n3,0,0,1,0.9\n4,three,4,1,0.9\n")
            result = run(folder)
            self.assertNotEqual(result.returncode, 0)
            self.assertIn("landmarks.csv:3:", result.stderr)

    def test_a_missing_folder_is_an_error(self):
        result = run(os.path.join(tempfile.gettempdir(), "no-such-run-folder-semslam"))
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("no such file", result.stderr)


if __name__ == "__main__":
    unittest.main()
