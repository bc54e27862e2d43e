#!/usr/bin/env python3
"""The window sweep of --loop-closure-branches (docs/results.md, "Two branches at an ambiguous loop closure") as one
figure: left, each simulated log's ATE over `known` association's on the same log against the window W (one thin
line per log, the issue's bound 2 × dashed); right, the real logs' mean `da_accuracy_real` against W.

Usage: plot_loop_closure_branches.py SUMMARY.json --out FILE.png
SUMMARY.json is what python/results_loop_closure_branches.py's sweep_summary() writes: {"windows": [W, ...],
"simulations": {family: [[ATE / known ATE per W] per log]}, "real": {family: [mean da_accuracy_real per W]}}.
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Colour-blind-safe colours (Okabe-Ito), as plot_methods.py.
COLOURS = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("summary")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    with open(args.summary) as f:
        summary = json.load(f)
    windows = summary["windows"]
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for colour, (family, ratios) in zip(COLOURS, summary["simulations"].items()):
        for i, per_window in enumerate(ratios):
            left.plot(windows, per_window, color=colour, alpha=0.6, linewidth=1, marker="o", markersize=3,
                      label=family if i == 0 else None)
    left.axhline(2.0, color="black", linestyle="--", linewidth=1, label="2 × known (the issue's bound)")
    left.set_yscale("log")
    left.set_xlabel("window W [steps] (0: no branches)")
    left.set_ylabel("ATE / known association's ATE")
    left.set_xticks(windows)
    left.legend(fontsize=8)
    left.set_title("simulations, one line per log")
    for colour, (family, means) in zip(COLOURS[2:] + COLOURS, summary["real"].items()):
        right.plot(windows, means, color=colour, marker="o", label=family)
    right.set_xlabel("window W [steps] (0: no branches)")
    right.set_ylabel("mean da_accuracy_real")
    right.set_xticks(windows)
    right.set_ylim(0.0, 1.0)
    right.legend(fontsize=8)
    right.set_title("real logs")
    figure.suptitle("mm-nh with --loop-closure-branches W")
    figure.tight_layout()
    figure.savefig(args.out, dpi=110)


if __name__ == "__main__":
    main()
