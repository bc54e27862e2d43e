#!/usr/bin/env python3
"""Oracle edits of a measurement log (docs/measurement-log.md), to measure where association loses: each edit
removes one source of difficulty using the log's own truth, so that a run on the edited log shows what that source
costs. Diagnostics only: an estimator never sees truth; docs/results.md, "Where MRCLAM's association loss comes
from", uses them.

- `drop_clutter`: detections whose truth is "not-a-landmark" are removed (every other detection, its order and its
  fields kept; `unknown` truth is kept, as the metrics leave it out anyway);
- `true_odometry` (2D): each odometry increment between two steps that both have a true pose becomes the true
  relative motion x_{k-1}⁻¹ x_k (heading difference wrapped to (−π, π]); its stated covariance is kept, so the
  estimator weighs it as before; increments next to a step without truth are kept as recorded.

Usage: python3 python/oracle_logs.py LOG OUT [--drop-clutter] [--true-odometry]
Plain Python 3.
"""
import argparse
import json
import math
import os
import sys


def wrap(angle):
    """The angle in (−π, π]."""
    wrapped = math.remainder(angle, 2 * math.pi)
    return math.pi if wrapped == -math.pi else wrapped


def relative_pose_2d(a, b):
    """a⁻¹ b for 2D poses [x, y, θ]."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return [c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2])]


def edit(source, destination, drop_clutter=False, true_odometry=False):
    """Writes the edited log; returns counts {"clutter_dropped", "odometry_replaced", "odometry_kept"}."""
    counts = {"clutter_dropped": 0, "odometry_replaced": 0, "odometry_kept": 0}
    with open(source) as f:
        header = json.loads(next(f))
        steps = [json.loads(line) for line in f]
    if true_odometry and header.get("dimension") != 2:
        raise ValueError(f"{source}: --true-odometry is written for 2D logs, this one has dimension "
                         f"{header.get('dimension')}")
    previous_truth = None
    for step in steps:
        if drop_clutter:
            kept = [d for d in step["detections"] if d.get("truth") != "not-a-landmark"]
            counts["clutter_dropped"] += len(step["detections"]) - len(kept)
            step["detections"] = kept
        truth = step.get("true_pose")
        if true_odometry and step.get("odometry"):
            if truth is not None and previous_truth is not None:
                step["odometry"]["increment"] = relative_pose_2d(previous_truth, truth)
                counts["odometry_replaced"] += 1
            else:
                counts["odometry_kept"] += 1
        previous_truth = truth
    partial = destination + ".partial"  # written whole, then renamed: never a half-written log
    with open(partial, "w") as f:
        f.write(json.dumps(header) + "\n")
        for step in steps:
            f.write(json.dumps(step) + "\n")
    os.replace(partial, destination)
    return counts


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log", metavar="LOG")
    parser.add_argument("out", metavar="OUT")
    parser.add_argument("--drop-clutter", action="store_true", help="remove detections of not-a-landmark truth")
    parser.add_argument("--true-odometry", action="store_true", help="odometry from the true poses (2D)")
    args = parser.parse_args()
    if not os.path.exists(args.log):
        sys.exit(f"oracle_logs.py: {args.log}: no such file")
    try:
        counts = edit(args.log, args.out, args.drop_clutter, args.true_odometry)
    except ValueError as error:
        sys.exit(f"oracle_logs.py: {error}")
    print(f"wrote {args.out}: {counts['clutter_dropped']} clutter detections dropped, "
          f"{counts['odometry_replaced']} odometry increments from the truth, {counts['odometry_kept']} kept")


if __name__ == "__main__":
    main()
