#!/usr/bin/env python3
"""The association ceiling under pose errors (docs/association-front-end.md §8), as a curve.

Usage: /usr/bin/python3 python/plot_association_ceiling.py CEILING_CSV OUT_PNG

CEILING_CSV has the columns robot, draw (joint, independent, or empty for the unmoved ceiling), scale, seed and
da_accuracy_real, one row per run (python/results_association_ceiling.py writes it). The figure has
`da_accuracy_real` against the pose-error scale s, one colour per draw: each robot's mean over the seeds as a thin
line, the mean over the robots as a thick one; s = 0, the unmoved ceiling, starts both. The y axis spans 0 to 1.
"""

import argparse
import csv
import statistics
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DRAW_COLOUR = {"joint": "#2ca02c", "independent": "#d62728"}
DRAW_LABEL = {"joint": "joint (from the known-DA posterior)", "independent": "independent (each pose's marginal)"}


def read_curves(path):
    """{draw: {robot: [(scale, mean over seeds)]}}, each curve starting at the robot's unmoved ceiling (s = 0)."""
    runs = defaultdict(list)  # (robot, draw, scale) -> values
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            try:
                key = (int(row["robot"]), row["draw"], float(row["scale"]))
                runs[key].append(float(row["da_accuracy_real"]))
            except (KeyError, ValueError) as error:
                sys.exit(f"plot_association_ceiling.py: {path}: bad row {row}: {error}")
    if not runs:
        sys.exit(f"plot_association_ceiling.py: {path} holds no runs")
    unmoved = {robot: statistics.fmean(v) for (robot, draw, _), v in runs.items() if draw == ""}
    curves = defaultdict(dict)
    for (robot, draw, scale), values in sorted(runs.items()):
        if draw == "":
            continue
        curve = curves[draw].setdefault(robot, [(0.0, unmoved[robot])] if robot in unmoved else [])
        curve.append((scale, statistics.fmean(values)))
    return curves


def plot(curves, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for draw, robots in curves.items():
        colour = DRAW_COLOUR.get(draw, "#1f77b4")
        for points in robots.values():
            ax.plot([s for s, _ in points], [v for _, v in points], color=colour, alpha=0.35, linewidth=0.9)
        scales = sorted({s for points in robots.values() for s, _ in points})
        means = [statistics.fmean([v for points in robots.values() for t, v in points if t == s]) for s in scales]
        ax.plot(scales, means, color=colour, linewidth=2.4, marker="o", label=DRAW_LABEL.get(draw, draw))
    ax.set_xlabel("pose error scale s (times the known-DA uncertainty)")
    ax.set_ylabel("da_accuracy_real")
    ax.set_ylim(0.0, 1.02)
    ax.set_xlim(left=0.0)
    ax.grid(True, alpha=0.3)
    ax.set_title("Association ceiling under pose errors (MRCLAM, thin: one robot)", fontsize=10)
    ax.legend(loc="lower left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv")
    parser.add_argument("out")
    args = parser.parse_args()
    plot(read_curves(args.csv), args.out)


if __name__ == "__main__":
    main()
