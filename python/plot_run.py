#!/usr/bin/env python3
"""Draw a semslam run folder: estimated and true trajectory, landmarks, and covariance ellipses.

Usage: plot_run.py RUN_DIR [--compare OTHER_RUN_DIR ...] [--out FILE.png] [--every N] [--sigma S] [--title T]

Reads the files described in src/semslam/io/RunFolder.h: trajectory.tum, truth.tum (optional), landmarks.csv,
landmarks_truth.csv (optional), covariances.csv (optional). Ellipses are drawn at S standard deviations
(default 2) for every N-th pose (default: about 40 ellipses along the trajectory) and every landmark.
With --compare, the trajectories of other runs on the same log are drawn beside it (each its own colour and dash
pattern). A box in a corner gives each run's numbers from its metrics.json (ATE, DA accuracy, landmarks), as
`semslam run` and `semslam demo` print them. The truth is drawn wherever truth.tum has it (a log may have true
poses on some steps only).
"""
import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Ellipse  # noqa: E402


def read_tum(path):
    xs, ys = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            fields = line.split()
            xs.append(float(fields[1]))
            ys.append(float(fields[2]))
    return xs, ys


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def ellipse(x, y, cxx, cxy, cyy, sigma, **style):
    """The sigma-level ellipse of a 2x2 covariance, from its eigen-decomposition."""
    trace, det = cxx + cyy, cxx * cyy - cxy * cxy
    root = math.sqrt(max(trace * trace / 4.0 - det, 0.0))
    major, minor = trace / 2.0 + root, max(trace / 2.0 - root, 0.0)
    angle = 0.5 * math.degrees(math.atan2(2.0 * cxy, cxx - cyy))
    return Ellipse((x, y), 2 * sigma * math.sqrt(major), 2 * sigma * math.sqrt(minor), angle=angle, fill=False,
                   **style)


COMPARE_STYLES = [("tab:orange", "-."), ("tab:green", ":"), ("tab:purple", (0, (5, 1, 1, 1)))]


def method_and_numbers(run_dir):
    """(label, one line of numbers) from RUN_DIR/metrics.json; the folder name without it."""
    path = os.path.join(run_dir, "metrics.json")
    label = os.path.basename(os.path.normpath(run_dir))
    if not os.path.exists(path):
        return label, ""
    with open(path) as f:
        m = json.load(f)
    label = m.get("method", label)
    parts = []
    if isinstance(m.get("ate_rmse"), (int, float)):
        parts.append(f"ATE {m['ate_rmse']:.3f} m")
    if isinstance(m.get("da_accuracy"), (int, float)):
        parts.append(f"DA accuracy {m['da_accuracy']:.3f}")
    if isinstance(m.get("landmarks_estimated"), int):
        true = m.get("landmarks_true")
        parts.append(f"landmarks {m['landmarks_estimated']}" + (f" (true {true})" if isinstance(true, int) else ""))
    return label, ", ".join(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--out", help="PNG to write (default RUN_DIR/run.png)")
    parser.add_argument("--every", type=int, default=0, help="draw the ellipse of every N-th pose")
    parser.add_argument("--sigma", type=float, default=2.0, help="ellipse size in standard deviations")
    parser.add_argument("--title", default=None)
    parser.add_argument("--compare", action="append", default=[], metavar="RUN_DIR",
                        help="another run on the same log, drawn beside this one (repeatable)")
    args = parser.parse_args()

    trajectory = os.path.join(args.run_dir, "trajectory.tum")
    if not os.path.exists(trajectory):
        sys.exit(f"plot_run.py: {trajectory} not found: not a run folder")
    est_x, est_y = read_tum(trajectory)
    figure, axes = plt.subplots(figsize=(8, 7))

    truth = os.path.join(args.run_dir, "truth.tum")
    if os.path.exists(truth):
        true_x, true_y = read_tum(truth)
        axes.plot(true_x, true_y, "--", color="0.4", linewidth=1.2, label="true trajectory")
    label, numbers = method_and_numbers(args.run_dir)
    summary = [f"{label}: {numbers}"] if numbers else []
    axes.plot(est_x, est_y, "-", color="tab:blue", linewidth=1.5,
              label=f"estimated trajectory ({label})" if args.compare else "estimated trajectory")
    for other, (colour, dashes) in zip(args.compare, COMPARE_STYLES * 10):
        other_trajectory = os.path.join(other, "trajectory.tum")
        if not os.path.exists(other_trajectory):
            sys.exit(f"plot_run.py: {other_trajectory} not found: not a run folder")
        other_label, other_numbers = method_and_numbers(other)
        xs, ys = read_tum(other_trajectory)
        axes.plot(xs, ys, color=colour, linestyle=dashes, linewidth=1.3, label=f"estimated trajectory ({other_label})")
        if other_numbers:
            summary.append(f"{other_label}: {other_numbers}")

    true_landmarks = read_csv(os.path.join(args.run_dir, "landmarks_truth.csv"))
    if true_landmarks:
        axes.plot([float(l["x"]) for l in true_landmarks], [float(l["y"]) for l in true_landmarks], "o",
                  markerfacecolor="none", markeredgecolor="0.3", markersize=9, label="true landmarks")
    landmarks = read_csv(os.path.join(args.run_dir, "landmarks.csv"))
    positions = {l["id"]: (float(l["x"]), float(l["y"])) for l in landmarks}
    if landmarks:
        axes.plot([p[0] for p in positions.values()], [p[1] for p in positions.values()], "x", color="tab:red",
                  markersize=8, label="estimated landmarks")

    every = args.every or max(1, len(est_x) // 40)
    drawn = False
    for row in read_csv(os.path.join(args.run_dir, "covariances.csv")):
        cxx, cxy, cyy = float(row["cxx"]), float(row["cxy"]), float(row["cyy"])
        if row["kind"] == "pose":
            index = int(row["id"])
            if index % every != 0 or index >= len(est_x):
                continue
            x, y, color = est_x[index], est_y[index], "tab:blue"
        else:
            if row["id"] not in positions:
                continue
            (x, y), color = positions[row["id"]], "tab:red"
        axes.add_patch(ellipse(x, y, cxx, cxy, cyy, args.sigma, edgecolor=color, linewidth=0.8,
                               label=None if drawn else f"{args.sigma:g}-sigma ellipses"))
        drawn = True

    axes.set_aspect("equal", adjustable="datalim")
    axes.set_xlabel("x [m]")
    axes.set_ylabel("y [m]")
    axes.grid(True, linewidth=0.3)
    axes.legend(loc="best", fontsize=9)
    if summary:
        axes.text(0.01, 0.01, "\n".join(summary), transform=axes.transAxes, fontsize=8, va="bottom", ha="left",
                  family="monospace", bbox={"boxstyle": "round", "facecolor": "white", "alpha": 0.85})
    axes.set_title(args.title or os.path.basename(os.path.normpath(args.run_dir)), fontsize=10)
    out = args.out or os.path.join(args.run_dir, "run.png")
    figure.tight_layout()
    figure.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
