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
- `odometry_bias_window` (2D, seconds W): only the odometry's slowly varying error is removed, what a bias state
  could at best estimate. Each increment between two steps with a true pose has an error rate
  e_k = (u_k − u_k^true) / Δt_k, per component (x, y and heading wrapped, in the body frame); every increment of the
  log then loses b̄_k Δt_k, b̄_k the mean of the e_i whose step lies within W/2 seconds of step k's time (an
  increment with no such e_i is kept). A constant bias is removed exactly; the error that varies faster than W is
  kept. Its stated covariance is kept.
- `drop_detections`: the detections at the given (step index, detection index) pairs are removed (used by
  python/landmark_motion_evidence.py to drop what a run left on landmarks its evidence flags).

Usage: python3 python/oracle_logs.py LOG OUT [--drop-clutter] [--true-odometry] [--odometry-bias-from-truth W]
Plain Python 3.
"""
import argparse
import bisect
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


def odometry_error_rates(steps):
    """[(time, [e_x, e_y, e_θ])] per odometry increment between two steps with a true pose: the increment's error
    against the true relative motion, per second (heading wrapped)."""
    rates = []
    for previous, step in zip(steps, steps[1:]):
        elapsed = step["time"] - previous["time"]
        if not step.get("odometry") or previous.get("true_pose") is None or step.get("true_pose") is None:
            continue
        if elapsed <= 0:
            continue
        truth = relative_pose_2d(previous["true_pose"], step["true_pose"])
        measured = step["odometry"]["increment"]
        error = [measured[0] - truth[0], measured[1] - truth[1], wrap(measured[2] - truth[2])]
        rates.append((step["time"], [e / elapsed for e in error]))
    return rates


def remove_odometry_bias(steps, window):
    """Subtracts from each increment the mean error rate within window/2 seconds times its Δt (module comment);
    returns how many increments changed."""
    rates = odometry_error_rates(steps)
    times = [t for t, _ in rates]
    changed = 0
    for previous, step in zip(steps, steps[1:]):
        if not step.get("odometry"):
            continue
        low = bisect.bisect_left(times, step["time"] - window / 2)
        high = bisect.bisect_right(times, step["time"] + window / 2)
        if high <= low:
            continue
        elapsed = step["time"] - previous["time"]
        increment = step["odometry"]["increment"]
        for c in range(3):
            increment[c] -= sum(rates[i][1][c] for i in range(low, high)) / (high - low) * elapsed
        increment[2] = wrap(increment[2])
        changed += 1
    return changed


def edit(source, destination, drop_clutter=False, true_odometry=False, odometry_bias_window=None,
         drop_detections=None):
    """Writes the edited log; returns counts {"clutter_dropped", "odometry_replaced", "odometry_kept",
    "odometry_debiased", "detections_dropped"}."""
    counts = {"clutter_dropped": 0, "odometry_replaced": 0, "odometry_kept": 0, "odometry_debiased": 0,
              "detections_dropped": 0}
    with open(source) as f:
        header = json.loads(next(f))
        steps = [json.loads(line) for line in f]
    odometry_edit = ("--true-odometry" if true_odometry else
                     "--odometry-bias-from-truth" if odometry_bias_window else None)
    if odometry_edit and header.get("dimension") != 2:
        raise ValueError(f"{source}: {odometry_edit} is written for 2D logs, this one has dimension "
                         f"{header.get('dimension')}")
    if true_odometry and odometry_bias_window:
        raise ValueError("--true-odometry and --odometry-bias-from-truth are two different edits: choose one")
    if odometry_bias_window is not None and not odometry_bias_window > 0:
        raise ValueError(f"--odometry-bias-from-truth: the window must be a positive number of seconds, got "
                         f"{odometry_bias_window}")
    if drop_detections:
        for k, step in enumerate(steps):
            kept = [d for i, d in enumerate(step["detections"]) if (k, i) not in drop_detections]
            counts["detections_dropped"] += len(step["detections"]) - len(kept)
            step["detections"] = kept
    if odometry_bias_window:
        counts["odometry_debiased"] = remove_odometry_bias(steps, odometry_bias_window)
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
    parser.add_argument("--odometry-bias-from-truth", type=float, metavar="W",
                        help="remove the odometry's error averaged over W seconds around each step (2D)")
    args = parser.parse_args()
    if not os.path.exists(args.log):
        sys.exit(f"oracle_logs.py: {args.log}: no such file")
    try:
        counts = edit(args.log, args.out, args.drop_clutter, args.true_odometry, args.odometry_bias_from_truth)
    except ValueError as error:
        sys.exit(f"oracle_logs.py: {error}")
    print(f"wrote {args.out}: {counts['clutter_dropped']} clutter detections dropped, "
          f"{counts['odometry_replaced']} odometry increments from the truth, {counts['odometry_kept']} kept, "
          f"{counts['odometry_debiased']} debiased")


if __name__ == "__main__":
    main()
