"""Edits a timestamped KITTI odometry pose file into another trajectory of the same kind: a part of it, or it driven
backwards. The simulations of docs/results.md run over KITTI sequences 00 and 07; an edited trajectory is a log the
project's defaults were not chosen on (docs/results.md, section "held-out-trajectories").

The file is the kind ../shared/data/kitti-odometry-poses holds and `semslam simulate semantic --trajectory-format
kitti` reads: one frame per line, 13 numbers, the time in seconds then the 3 × 4 pose [R | t] row by row.

  --frames FIRST:END  keeps frames FIRST to END − 1 (0-based; either end may be left out, as in a Python slice);
  --reverse           runs the frames in the opposite order: frame k of the output is frame n − 1 − k of the input,
                      at time t_last − t; each pose is kept as it is, so the camera keeps facing where it faced and
                      the vehicle backs along its path, seeing each place as it leaves it.

The output's times start at 0 (the first frame kept) and rise strictly; the pose numbers are copied as written. Bad
input (a line without 13 numbers, a number that is not finite, a time that does not rise, an empty selection) is
refused with the file, the line and the problem, exit status 2; the output is written completely or not at all.

Usage: edit_trajectory.py IN --out OUT [--frames FIRST:END] [--reverse]
"""
import argparse
import math
import os
import sys


class TrajectoryError(Exception):
    """Bad input: the message names the file, the line where there is one, and the problem."""


def read_frames(path):
    """[(time, [12 pose numbers as written])] of a timestamped KITTI pose file; blank lines are skipped."""
    frames = []
    with open(path) as f:
        for number, line in enumerate(f, start=1):
            fields = line.split()
            if not fields:
                continue
            if len(fields) != 13:
                raise TrajectoryError(f"{path}:{number}: {len(fields)} numbers, expected 13 (time, then the 3 × 4 "
                                      "pose row by row)")
            try:
                values = [float(field) for field in fields]
            except ValueError:
                raise TrajectoryError(f"{path}:{number}: not a number in '{line.strip()}'") from None
            if not all(math.isfinite(value) for value in values):
                raise TrajectoryError(f"{path}:{number}: a number that is not finite")
            if frames and values[0] <= frames[-1][0]:
                raise TrajectoryError(f"{path}:{number}: time {fields[0]} does not rise (previous frame "
                                      f"{frames[-1][0]!r})")
            frames.append((values[0], fields[1:]))
    if not frames:
        raise TrajectoryError(f"{path}: no frames")
    return frames


def parse_frames(text):
    """FIRST:END of --frames as a slice; either end may be empty."""
    first, colon, end = text.partition(":")
    if not colon:
        raise TrajectoryError(f"--frames {text}: expected FIRST:END")
    try:
        return slice(int(first) if first else None, int(end) if end else None)
    except ValueError:
        raise TrajectoryError(f"--frames {text}: FIRST and END must be whole numbers") from None


def frames_text(selection):
    """The FIRST:END of --frames that `selection` is (the inverse of parse_frames)."""
    return ":".join("" if end is None else str(end) for end in (selection.start, selection.stop))


def edit(frames, selection=slice(None), reverse=False):
    """The frames kept by `selection`, reversed in order and in time when `reverse`, re-timed to start at 0."""
    kept = frames[selection]
    if not kept:
        raise TrajectoryError(f"--frames {frames_text(selection)} selects none of the trajectory's {len(frames)} "
                              "frames")
    if reverse:
        last = kept[-1][0]
        return [(last - time, pose) for time, pose in reversed(kept)]
    first = kept[0][0]
    return [(time - first, pose) for time, pose in kept]


def time_text(seconds):
    """A time to the nanosecond, without trailing zeros (round-off of the subtraction removed)."""
    text = f"{seconds:.9f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def write_frames(path, frames):
    """Writes the frames completely or not at all (a temporary file beside `path`, then renamed)."""
    temporary = path + ".tmp"
    with open(temporary, "w") as f:
        for time, pose in frames:
            f.write(" ".join([time_text(time)] + pose) + "\n")
    os.replace(temporary, path)


def main(arguments):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("--out", required=True, help="the edited pose file")
    parser.add_argument("--frames", default=":", help="FIRST:END, the frames kept (0-based, END excluded)")
    parser.add_argument("--reverse", action="store_true", help="drive the trajectory backwards")
    options = parser.parse_args(arguments)
    try:
        frames = edit(read_frames(options.input), parse_frames(options.frames), options.reverse)
        write_frames(options.out, frames)
    except (TrajectoryError, OSError) as error:
        print(f"edit_trajectory.py: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
