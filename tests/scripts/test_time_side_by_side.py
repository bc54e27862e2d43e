"""python/time_side_by_side.py, the side-by-side timer docs/ quotes its cost ratios from: the ratio is candidate /
baseline (not inverted), both commands run the asked number of times after the warm-up, a failing run stops the
call with exit 1 and no figure, a command that cannot start is named, and missing commands are refused.

Usage: test_time_side_by_side.py
"""
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "python", "time_side_by_side.py")


def run(*arguments):
    return subprocess.run([sys.executable, "-B", SCRIPT, *arguments], capture_output=True, text=True, check=False)


class TimeSideBySide(unittest.TestCase):
    def test_the_ratio_is_candidate_over_baseline(self):
        # A half-second sleep against a command that returns at once: the ratio must be far above 1 (inverted, it
        # would be far below). Not a timing claim about our code: the direction of the quotient.
        result = run("-n", "2", "--warmup", "0", "--vs", "true", "--", "sleep", "0.5")
        self.assertEqual(result.returncode, 0, result.stderr)
        ratio = re.search(r"ratio candidate/baseline, wall: ([0-9.e+]+)", result.stdout)
        self.assertIsNotNone(ratio, result.stdout)
        self.assertGreater(float(ratio.group(1)), 5.0)
        self.assertIn("candidate: sleep 0.5", result.stdout)
        self.assertIn("baseline:  true", result.stdout)
        self.assertIn("runs: 2 pairs after 0 warm-up pair(s)", result.stdout)

    def test_each_command_runs_warmup_plus_runs_times(self):
        with tempfile.TemporaryDirectory() as directory:
            candidate = os.path.join(directory, "candidate")
            baseline = os.path.join(directory, "baseline")
            result = run("-n", "3", "--warmup", "2", "--vs", f"sh -c 'echo >> {baseline}'", "--",
                         "sh", "-c", f"echo >> {candidate}")
            self.assertEqual(result.returncode, 0, result.stderr)
            for path in (candidate, baseline):
                with open(path, encoding="utf-8") as lines:
                    self.assertEqual(len(lines.readlines()), 5, path)

    def test_a_failing_run_gives_no_figure(self):
        result = run("-n", "2", "--vs", "true", "--", "false")
        self.assertEqual(result.returncode, 1)
        self.assertNotIn("ratio", result.stdout)
        self.assertIn("false exited with 1", result.stderr)

    def test_a_command_that_cannot_start_is_named(self):
        result = run("-n", "1", "--vs", "true", "--", "/nonexistent/semslam")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("cannot start '/nonexistent/semslam'", result.stderr)

    def test_missing_commands_are_refused(self):
        self.assertEqual(run("--vs", "true").returncode, 2)
        self.assertEqual(run("--", "true").returncode, 2)
        self.assertEqual(run("-n", "0", "--vs", "true", "--", "true").returncode, 2)


if __name__ == "__main__":
    unittest.main()
