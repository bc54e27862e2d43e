"""docs/results.md section `loop-closure-open-splits`: a loop-closure split opening inside another's branches (two open
splits, the default where branches apply; docs/association-front-end.md §10, "Splits within splits") against one
split at a time (`--loop-closure-open-splits 1`), on every log family of the window sweep
(results_loop_closure_branches.py: MRCLAM Dataset 6 robots 1-5 × label seeds 1-3, KITTI tracking 0000-0010 at 1 Hz
×5, Lost in the Woods, the KITTI 00 and 07 simulations with seeds 1-8). `mm-nh` with its defaults otherwise (W = 16,
three branches); every cell comes from the runs' metrics.json and branches.csv. Used by make_results.py.
"""
import os

from results_commands import read_metrics
from results_loop_closure_branches import NO_LOGS, compare_variants
from results_loop_closure_next_best import comparison_table, kept_counts

VARIANTS = [("one split at a time", ["--loop-closure-open-splits", "1"]), ("two open splits (the default)", [])]


def listed_splits(variant_folders):
    """The cell "splits listed, each variant": the splits of the kept runs' branches.csv (a split dropped with the
    branch it opened in is not listed), summed over the family's runs, one figure per variant."""
    return " / ".join(str(sum(kept_counts(folder)[0] for folder in variant)) for variant in variant_folders)


def simulation_ate_rows(families, folders):
    """Each simulated family's ATE per seed, each variant and `known` association: where the variants differ."""
    lines = []
    for family, (kind, logs) in families.items():
        if kind != "simulation":
            continue
        lines += ["", f"{family}, ATE [m] per log:", "",
                  "| variant | " + " | ".join(name for name, _ in logs) + " |", "|---|" + "---|" * len(logs)]
        for key, label in list(enumerate(label for label, _ in VARIANTS)) + [("known", "`known`")]:
            ates = [read_metrics(folders[(family, name, key)])["ate_rmse"] for name, _ in logs]
            lines.append(f"| {label} | " + " | ".join(f"{a:.3f}" for a in ates) + " |")
    return lines


def loop_closure_open_splits_section(semslam, data, scratch, shown):
    lines = ["## Splits within splits at ambiguous loop closures (issue 10)", ""]
    runs = compare_variants(semslam, data, os.path.join(scratch, "loop-closure-open-splits"), VARIANTS, "o")
    if runs is None:
        return lines + [NO_LOGS, ""]
    families, folders = runs
    lines += ["`mm-nh` with its defaults (W = 16, three branches, two splits open at a time: a branch of an open "
              "split may split again; docs/association-front-end.md §10) and with `--loop-closure-open-splits 1`. "
              "MRCLAM: mean `da_accuracy_real` (robots 1-5 × label seeds 1-3); "
              "KITTI tracking: mean `da_accuracy_real` / mean `clutter_rejected_moving` over 0000-0010; Lost in the "
              "Woods: `da_accuracy_real` / ATE [m]; KITTI 00 and 07: seeds within 2 × `known` association's ATE on "
              "the same log, mean ATE [m]. *up / down*: logs where two open splits do better / worse "
              "(`da_accuracy_real`; ATE for the simulations). *time*: the sum of the runs' `time_s`, on a machine "
              "shared with the other runs of the section.", ""]
    lines += comparison_table(families, folders, VARIANTS, times_header="one / two open",
                              counts_header="splits listed (one / two open)", counts=listed_splits)
    lines += simulation_ate_rows(families, folders)
    lines += ["", "```sh",
              shown([semslam, "run", "--method", "mm-nh", "--in", "LOG", "--out", "DIR", "--no-covariances",
                     "[--loop-closure-open-splits 1]"]),
              "```",
              "LOG: as in the window sweep above.", ""]
    return lines
