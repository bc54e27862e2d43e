#!/usr/bin/env python3
"""Trajectories of several methods against the ground truth on one figure (paper B's Fig. 4/5 analog).

Usage: plot_methods.py RUN_DIR [RUN_DIR ...] --out FILE.png [--title TEXT]
       plot_methods.py --log LOG --methods known,ml,mm-nh --out FILE.png [--option KEY=VALUE ...]

Each RUN_DIR is a `semslam run` output folder (src/semslam/io/RunFolder.h); its folder name is the method's label,
with its ATE and DA accuracy from metrics.json. With --log, the methods run in this process through the Python
module (docs/python.md; build/python on PYTHONPATH), with no run folder written: each --option is a `semslam run`
flag with _ for - (`--option gate=0.95 --option no_covariances=True`), given to every method.
Each method has its own colour and dash pattern, so overlapping lines stay apart.
The truth is taken from the first folder that has truth.tum (from the log with --log); true landmarks from
landmarks_truth.csv (the log's header). 3D runs are drawn from above (x, y). Trajectories are drawn as estimated
(every method starts at the log's first-pose prior, so they share the truth's frame); no alignment is applied.
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
    metrics = os.path.join(run, "metrics.json")
    values = {}
    if os.path.exists(metrics):
        with open(metrics) as f:
            values = json.load(f)
    return label_with_metrics(os.path.basename(os.path.normpath(run)), values)


def label_with_metrics(name, metrics):
    parts = []
    if isinstance(metrics.get("ate_rmse"), (int, float)):
        parts.append(f"ATE {metrics['ate_rmse']:.3f} m")
    if isinstance(metrics.get("da_accuracy"), (int, float)):
        parts.append(f"DA {metrics['da_accuracy']:.3f}")
    return name + (" (" + ", ".join(parts) + ")" if parts else "")


def series_from_run_folders(runs):
    """(truth xs, ys) or None, true landmarks [(x, y)], and [(label, xs, ys)] from run folders."""
    truth, true_landmarks, series = None, [], []
    for run in runs:
        trajectory = os.path.join(run, "trajectory.tum")
        if not os.path.exists(trajectory):
            sys.exit(f"plot_methods.py: {trajectory} not found")
        truth_file = os.path.join(run, "truth.tum")
        if truth is None and os.path.exists(truth_file):
            truth = read_tum(truth_file)
            landmarks = os.path.join(run, "landmarks_truth.csv")
            if os.path.exists(landmarks):
                with open(landmarks) as f:
                    true_landmarks = [(float(r["x"]), float(r["y"])) for r in csv.DictReader(f)]
        series.append((label_of(run),) + read_tum(trajectory))
    return truth, true_landmarks, series


def parse_option(text):
    """KEY=VALUE with VALUE as Python reads a literal (0.95, 3, True), else as a string (threshold)."""
    import ast

    key, separator, value = text.partition("=")
    if not separator:
        sys.exit(f"plot_methods.py: --option {text}: expected KEY=VALUE")
    try:
        return key, ast.literal_eval(value)
    except (ValueError, SyntaxError):
        return key, value


def series_from_module(log_path, methods, options):
    """The same three things, running each method through the Python module (no files written)."""
    try:
        import semslam
    except ImportError:
        sys.exit("plot_methods.py: --log needs the Python module: `make build`, then PYTHONPATH=build/python")
    try:
        log = semslam.read_log(log_path)
        results = [semslam.run(method, log, **options) for method in methods]
    except (ValueError, TypeError) as error:
        sys.exit(f"plot_methods.py: {error}")
    truth = None
    if log.true_trajectory is not None:
        truth = (list(log.true_trajectory[:, 0]), list(log.true_trajectory[:, 1]))
    landmarks = log.landmark_truth
    true_landmarks = [] if landmarks is None else [tuple(p[:2]) for p in landmarks["position"]]
    series = [(label_with_metrics(r.method, r.metrics), list(r.trajectory[:, 0]), list(r.trajectory[:, 1]))
              for r in results]
    return truth, true_landmarks, series


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="*", help="run folders (or use --log)")
    parser.add_argument("--log", help="a measurement log: run --methods on it through the Python module")
    parser.add_argument("--methods", default="known,ml,gpda,mm,mm-nh", help="with --log: comma-separated")
    parser.add_argument("--option", action="append", default=[], metavar="KEY=VALUE",
                        help="with --log: a `semslam run` flag for every method, _ for - (repeatable)")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="Trajectories of each method against the ground truth")
    args = parser.parse_args()
    if bool(args.runs) == bool(args.log):
        parser.error("give run folders or --log, not both")

    if args.log:
        options = dict(parse_option(text) for text in args.option)
        truth, true_landmarks, series = series_from_module(args.log, args.methods.split(","), options)
    else:
        truth, true_landmarks, series = series_from_run_folders(args.runs)

    figure, axes = plt.subplots(figsize=(8, 7))
    if truth is not None:
        axes.plot(*truth, color="black", linewidth=2.5, alpha=0.35, label="ground truth")
        if true_landmarks:
            axes.scatter([p[0] for p in true_landmarks], [p[1] for p in true_landmarks], marker="*", s=80,
                         color="black", label="true landmarks", zorder=5)
    for index, (label, xs, ys) in enumerate(series):
        axes.plot(xs, ys, linewidth=1.3, color=COLOURS[index % len(COLOURS)],
                  linestyle=DASHES[index % len(DASHES)], label=label)
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_xlabel("x [m]")
    axes.set_ylabel("y [m]")
    if truth is None:
        axes.text(0.01, 0.01, "no ground truth in these runs", transform=axes.transAxes, fontsize=8)
    axes.set_title(args.title)
    axes.legend(loc="best", fontsize=8)
    figure.tight_layout()
    temporary = args.out + ".tmp.png"
    figure.savefig(temporary, dpi=130)
    os.replace(temporary, args.out)


if __name__ == "__main__":
    main()
