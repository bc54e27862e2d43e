#!/usr/bin/env python3
"""Draw a semslam run folder: estimated and true trajectory, landmarks, and covariance ellipses.

Usage: plot_run.py RUN_DIR [--out FILE.png] [--every N] [--sigma S]

Reads the files described in src/semslam/io/RunFolder.h: trajectory.tum, truth.tum (optional), landmarks.csv,
landmarks_truth.csv (optional), covariances.csv (optional). Ellipses are drawn at S standard deviations
(default 2) for every N-th pose (default: about 40 ellipses along the trajectory) and every landmark.
"""
import argparse
import csv
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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--out", help="PNG to write (default RUN_DIR/run.png)")
    parser.add_argument("--every", type=int, default=0, help="draw the ellipse of every N-th pose")
    parser.add_argument("--sigma", type=float, default=2.0, help="ellipse size in standard deviations")
    parser.add_argument("--title", default=None)
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
    axes.plot(est_x, est_y, "-", color="tab:blue", linewidth=1.5, label="estimated trajectory")

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
    axes.set_title(args.title or os.path.basename(os.path.normpath(args.run_dir)))
    out = args.out or os.path.join(args.run_dir, "run.png")
    figure.tight_layout()
    figure.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
