#!/usr/bin/env python3
"""Trajectories of several methods against the ground truth on one figure (paper B's Fig. 4/5 analog).

Usage: plot_methods.py RUN_DIR [RUN_DIR ...] --out FILE.png [--title TEXT]

Each RUN_DIR is a `semslam run` output folder (src/semslam/io/RunFolder.h); its folder name is the method's label.
The truth is taken from the first folder that has truth.tum; true landmarks from landmarks_truth.csv. 3D runs are
drawn from above (x, y). Trajectories are drawn as estimated (every method starts at the log's first-pose prior,
so they share the truth's frame); no alignment is applied.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_run import read_tum  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    figure, axes = plt.subplots(figsize=(8, 7))
    truth_drawn = False
    for run in args.runs:
        trajectory = os.path.join(run, "trajectory.tum")
        if not os.path.exists(trajectory):
            sys.exit(f"plot_methods.py: {trajectory} not found")
        truth = os.path.join(run, "truth.tum")
        if not truth_drawn and os.path.exists(truth):
            xs, ys = read_tum(truth)
            axes.plot(xs, ys, color="black", linewidth=2.5, alpha=0.35, label="ground truth")
            landmarks = os.path.join(run, "landmarks_truth.csv")
            if os.path.exists(landmarks):
                with open(landmarks) as f:
                    rows = list(csv.DictReader(f))
                axes.scatter([float(r["x"]) for r in rows], [float(r["y"]) for r in rows], marker="*", s=80,
                             color="black", label="true landmarks", zorder=5)
            truth_drawn = True
        xs, ys = read_tum(trajectory)
        axes.plot(xs, ys, linewidth=1.0, label=os.path.basename(os.path.normpath(run)))
    axes.set_aspect("equal")
    axes.set_xlabel("x [m]")
    axes.set_ylabel("y [m]")
    if args.title:
        axes.set_title(args.title)
    axes.legend(loc="best", fontsize=8)
    figure.tight_layout()
    temporary = args.out + ".tmp.png"
    figure.savefig(temporary, dpi=130)
    os.replace(temporary, args.out)


if __name__ == "__main__":
    main()
