#!/usr/bin/env python3
"""Trajectories of several methods against the ground truth on one figure (paper B's Fig. 4/5 analog).

Usage: plot_methods.py RUN_DIR [RUN_DIR ...] --out FILE.png [--title TEXT]

Each RUN_DIR is a `semslam run` output folder (src/semslam/io/RunFolder.h); its folder name is the method's label,
with its ATE and DA accuracy from metrics.json. Each method has its own colour and dash pattern, so overlapping
lines stay apart.
The truth is taken from the first folder that has truth.tum; true landmarks from landmarks_truth.csv. 3D runs are
drawn from above (x, y). Trajectories are drawn as estimated (every method starts at the log's first-pose prior,
so they share the truth's frame); no alignment is applied.
"""
import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_run import read_tum  # noqa: E402


# Colour-blind-safe colours (Okabe-Ito) and dash patterns, so lines that lie on each other stay distinguishable.
COLOURS = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442"]
DASHES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)), (0, (1, 1))]


def label_of(run):
    """The folder name, with the run's ATE and DA accuracy when its metrics.json has them."""
    label = os.path.basename(os.path.normpath(run))
    metrics = os.path.join(run, "metrics.json")
    if os.path.exists(metrics):
        with open(metrics) as f:
            m = json.load(f)
        parts = []
        if isinstance(m.get("ate_rmse"), (int, float)):
            parts.append(f"ATE {m['ate_rmse']:.3f} m")
        if isinstance(m.get("da_accuracy"), (int, float)):
            parts.append(f"DA {m['da_accuracy']:.3f}")
        if parts:
            label += " (" + ", ".join(parts) + ")"
    return label


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="Trajectories of each method against the ground truth")
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
        index = args.runs.index(run)
        axes.plot(xs, ys, linewidth=1.3, color=COLOURS[index % len(COLOURS)],
                  linestyle=DASHES[index % len(DASHES)], label=label_of(run))
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_xlabel("x [m]")
    axes.set_ylabel("y [m]")
    if not truth_drawn:
        axes.text(0.01, 0.01, "no ground truth in these runs", transform=axes.transAxes, fontsize=8)
    axes.set_title(args.title)
    axes.legend(loc="best", fontsize=8)
    figure.tight_layout()
    temporary = args.out + ".tmp.png"
    figure.savefig(temporary, dpi=130)
    os.replace(temporary, args.out)


if __name__ == "__main__":
    main()
