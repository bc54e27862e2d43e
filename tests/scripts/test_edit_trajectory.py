"""python/edit_trajectory.py on hand-made pose files (no data): a part, the reversal (order, times, poses copied as
written), and bad input refused with the file, the line and exit status 2, no output left behind.

Usage: test_edit_trajectory.py
"""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import edit_trajectory  # noqa: E402


def pose(x):
    """A 3 × 4 pose row by row, as text, at position (x, 0, 2x)."""
    return f"1 0 0 {x} 0 1 0 0 0 0 1 {2 * x}"


class EditTrajectory(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.input = os.path.join(self.scratch.name, "in.txt")
        self.output = os.path.join(self.scratch.name, "out.txt")
        # Five frames at 10.0, 10.1037359, 10.2, 10.35, 10.5 s (a KITTI-like irregular step), x = frame index.
        self.write(["10.0 " + pose(0), "10.1037359 " + pose(1), "", "10.2 " + pose(2), "10.35 " + pose(3),
                    "10.5 " + pose(4)])

    def tearDown(self):
        self.scratch.cleanup()

    def write(self, lines):
        with open(self.input, "w") as f:
            f.write("\n".join(lines) + "\n")

    def edited(self, *options):
        self.assertEqual(edit_trajectory.main([self.input, "--out", self.output] + list(options)), 0)
        with open(self.output) as f:
            return [line.split(" ", 1) for line in f.read().splitlines()]

    def test_unedited_it_is_the_input_retimed_to_start_at_zero(self):
        rows = self.edited()
        self.assertEqual([time for time, _ in rows], ["0", "0.1037359", "0.2", "0.35", "0.5"])
        self.assertEqual([p for _, p in rows], [pose(k) for k in range(5)])

    def test_a_part_keeps_its_frames_and_starts_at_zero(self):
        rows = self.edited("--frames", "1:4")
        self.assertEqual([time for time, _ in rows], ["0", "0.0962641", "0.2462641"])
        self.assertEqual([p for _, p in rows], [pose(1), pose(2), pose(3)])
        self.assertEqual([p for _, p in self.edited("--frames", "3:")], [pose(3), pose(4)])
        self.assertEqual([p for _, p in self.edited("--frames", ":2")], [pose(0), pose(1)])

    def test_reversed_the_last_frame_comes_first_and_the_times_are_mirrored(self):
        rows = self.edited("--reverse")
        self.assertEqual([p for _, p in rows], [pose(k) for k in (4, 3, 2, 1, 0)])  # poses copied as written
        self.assertEqual([time for time, _ in rows], ["0", "0.15", "0.3", "0.3962641", "0.5"])
        # Reversing twice gives the input back, retimed.
        with open(self.output) as f:
            reversed_text = f.read()
        with open(self.input, "w") as f:
            f.write(reversed_text)
        self.assertEqual([p for _, p in self.edited("--reverse")], [pose(k) for k in range(5)])

    def test_a_reversed_part(self):
        rows = self.edited("--frames", "2:", "--reverse")
        self.assertEqual([p for _, p in rows], [pose(4), pose(3), pose(2)])
        self.assertEqual([time for time, _ in rows], ["0", "0.15", "0.3"])

    def refused(self, lines, *options, message):
        self.write(lines)
        with self.assertRaises(edit_trajectory.TrajectoryError) as raised:
            edit_trajectory.edit(edit_trajectory.read_frames(self.input),
                                 edit_trajectory.parse_frames(options[0] if options else ":"))
        self.assertIn(message, str(raised.exception))
        self.assertEqual(edit_trajectory.main([self.input, "--out", self.output] + list(("--frames",) + options
                                                                                 if options else ())), 2)
        self.assertFalse(os.path.exists(self.output))
        self.assertFalse(os.path.exists(self.output + ".tmp"))

    def test_bad_input_names_the_file_and_line_and_writes_nothing(self):
        good = "0.0 " + pose(0)
        self.refused([good, "0.1 1 0 0"], message="in.txt:2: 4 numbers, expected 13")
        self.refused([good, "0.1 " + pose(1).replace("0 1 0", "0 x 0", 1)], message="in.txt:2: not a number")
        self.refused([good, "0.1 " + pose(1).replace("1", "nan", 1)], message="in.txt:2: a number that is not finite")
        self.refused([good, "0.0 " + pose(1)], message="in.txt:2: time 0.0 does not rise")
        self.refused([], message="in.txt: no frames")
        self.refused([good], "1:", message="--frames 1: selects none of the trajectory's 1 frames")
        self.refused([good], "a:b", message="FIRST and END must be whole numbers")
        self.refused([good], "3", message="expected FIRST:END")


if __name__ == "__main__":
    unittest.main()
