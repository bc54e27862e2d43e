#!/usr/bin/env python3
"""Box plots of a `semslam study robustness` folder, like paper B's Fig. 3.

Usage: /usr/bin/python3 python/plot_robustness.py DIR [--metrics ate_rmse,rot_rmse,da_accuracy]

Reads DIR/robustness.csv (and DIR/timings.csv for the metric time_s: wall-clock times live there, so that
robustness.csv is the same for any threads and MPI ranks) and writes DIR/robustness_<metric>.png for each metric:
two panels, (a) the odometry noise sweep and (b) the misclassification sweep; per level one box per method (seeds
are the samples), methods in a fixed colour. Also DIR/robustness.png: all metrics in one figure (rows: metrics, columns: sweeps).
The y axes do not exaggerate differences: fractions (DA accuracy) span 0 to 1, errors and counts start at 0.
"""

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

METHOD_ORDER = ["known", "ml", "gpda", "mm", "mm-nh"]
METHOD_LABEL = {"known": "Known DA", "ml": "ML", "gpda": "GPDA", "mm": "MM", "mm-nh": "MM+NH"}
METHOD_COLOUR = {"known": "#4d4d4d", "ml": "#d62728", "gpda": "#ff7f0e", "mm": "#1f77b4", "mm-nh": "#2ca02c"}
AXES = [("odom_noise", "odometry noise scale"), ("misclassification", "misclassification rate")]
METRIC_LABEL = {"ate_rmse": "ATE RMSE (m)", "rot_rmse": "rotation RMSE (rad)", "da_accuracy": "DA accuracy",
                "da_accuracy_real": "DA accuracy (true landmarks)",
                "landmarks_estimated": "landmarks estimated", "time_s": "time (s)"}


# Metrics that are fractions in [0, 1]: drawn on 0..1 so that 0.999 against 1.0 looks as small as it is.
FRACTION_METRICS = {"da_accuracy", "da_accuracy_real", "pairwise_precision", "pairwise_recall", "clutter_rejected"}


def set_value_limits(ax, rows, metric):
    """Fixed limits: 0..1 for fractions; from 0 to a little above the largest value otherwise."""
    if metric in FRACTION_METRICS:
        ax.set_ylim(0.0, 1.03)
        return
    finite = [float(r[metric]) for r in rows if r.get(metric, "") != "" and math.isfinite(float(r[metric]))]
    top = max(finite) if finite else 1.0
    ax.set_ylim(0.0, top * 1.08 if top > 0 else 1.0)


def read_rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def read_study_rows(folder):
    """robustness.csv's rows, each with its run's time_s from timings.csv (the same run order) where present."""
    rows = read_rows(os.path.join(folder, "robustness.csv"))
    timings_path = os.path.join(folder, "timings.csv")
    if os.path.exists(timings_path):
        timings = read_rows(timings_path)
        if len(timings) != len(rows):
            sys.exit(f"plot_robustness.py: {timings_path} has {len(timings)} runs, robustness.csv {len(rows)}")
        for row, timing in zip(rows, timings):
            row["time_s"] = timing["time_s"]
    return rows


def values(rows, axis, level, method, metric):
    out = []
    for row in rows:
        if row["axis"] == axis and row["level"] == level and row["method"] == method and row[metric] != "":
            v = float(row[metric])
            if math.isfinite(v):
                out.append(v)
    return out


def draw_panel(ax, rows, axis, axis_label, metric, methods):
    levels = sorted({row["level"] for row in rows if row["axis"] == axis}, key=float)
    width = 0.8 / max(len(methods), 1)
    for m, method in enumerate(methods):
        data, positions = [], []
        for i, level in enumerate(levels):
            v = values(rows, axis, level, method, metric)
            if v:
                data.append(v)
                positions.append(i - 0.4 + width * (m + 0.5))
        if not data:
            continue
        boxes = ax.boxplot(data, positions=positions, widths=width * 0.85, patch_artist=True, manage_ticks=False,
                           flierprops={"markersize": 2})
        for box in boxes["boxes"]:
            box.set_facecolor(METHOD_COLOUR.get(method, "#999999"))
            box.set_alpha(0.8)
        for median in boxes["medians"]:
            median.set_color("black")
    ax.set_xticks(range(len(levels)))
    ax.set_xticklabels(levels)
    ax.set_xlim(-0.6, len(levels) - 0.4)
    set_value_limits(ax, rows, metric)
    ax.set_xlabel(axis_label)
    ax.set_ylabel(METRIC_LABEL.get(metric, metric))
    ax.grid(axis="y", alpha=0.3)


def legend_handles(methods):
    return [Patch(facecolor=METHOD_COLOUR.get(m, "#999999"), label=METHOD_LABEL.get(m, m)) for m in methods]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("--metrics", default="ate_rmse,rot_rmse,da_accuracy")
    args = parser.parse_args()
    path = os.path.join(args.folder, "robustness.csv")
    if not os.path.exists(path):
        sys.exit(f"plot_robustness.py: {path} not found")
    rows = read_study_rows(args.folder)
    present = {row["method"] for row in rows}
    methods = [m for m in METHOD_ORDER if m in present] + sorted(present - set(METHOD_ORDER))
    metrics = [m for m in args.metrics.split(",") if m]
    written = []
    for metric in metrics:
        fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
        for ax, (axis, label), tag in zip(axes, AXES, "ab"):
            draw_panel(ax, rows, axis, label, metric, methods)
            ax.set_title(f"({tag}) {label}")
        fig.suptitle(f"Robustness study: {METRIC_LABEL.get(metric, metric)} over paired seeds", y=0.99)
        fig.legend(handles=legend_handles(methods), loc="upper center", bbox_to_anchor=(0.5, 0.93),
                   ncol=len(methods), frameon=False)
        fig.tight_layout(rect=(0, 0, 1, 0.84))
        out = os.path.join(args.folder, f"robustness_{metric}.png")
        fig.savefig(out, dpi=120)
        plt.close(fig)
        written.append(out)
    fig, axes = plt.subplots(len(metrics), 2, figsize=(11, 3.2 * len(metrics)), squeeze=False)
    for r, metric in enumerate(metrics):
        for c, (axis, label) in enumerate(AXES):
            draw_panel(axes[r][c], rows, axis, label, metric, methods)
            if r == 0:
                axes[r][c].set_title(f"({'ab'[c]}) {label}")
    height = 3.2 * len(metrics)
    fig.suptitle("Robustness study over paired seeds (box: quartiles of the seeds)", y=1 - 0.05 / height)
    fig.legend(handles=legend_handles(methods), loc="upper center", bbox_to_anchor=(0.5, 1 - 0.35 / height),
               ncol=len(methods), frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.8 / height))
    out = os.path.join(args.folder, "robustness.png")
    fig.savefig(out, dpi=120)
    plt.close(fig)
    written.append(out)
    print("wrote " + ", ".join(written))


if __name__ == "__main__":
    main()
