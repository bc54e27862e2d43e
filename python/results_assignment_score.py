"""docs/results.md section `assignment-score`: the step's joint assignment scored by the joint density of its
pairings' innovations (joint compatibility branch and bound, the default since session 33;
docs/association-front-end.md §4) against the independent score (`--assignment-score independent`: each pairing by
its own likelihood, Hungarian), on every log family of the loop-closure window sweep (results_loop_closure_branches.py:
MRCLAM Dataset 6 robots 1-5 × label seeds 1-3, KITTI tracking 0000-0010 at 1 Hz ×5, Lost in the Woods, the KITTI 00
and 07 simulations with seeds 1-8). Two tables: whole runs (`mm-nh` with the independent score, then with its
defaults), and the front end's decisions on the true history (`--on-true-history`, docs/association-front-end.md §8b:
every decision taken on a history without error, so the two scores are compared decision for decision, free of the
path a run's own errors take). Every cell comes from the runs' metrics.json. Used by make_results.py.
"""
import os

from results_commands import mean_cell, read_metrics
from results_loop_closure_branches import NO_LOGS, compare_variants
from results_loop_closure_next_best import comparison_table, kept_counts

INDEPENDENT = ["--assignment-score", "independent"]
TRUE_HISTORY = ["--on-true-history"]
VARIANTS = [("independent", INDEPENDENT), ("joint (the default)", []),
            ("independent, on the true history", INDEPENDENT + TRUE_HISTORY),
            ("joint, on the true history", TRUE_HISTORY)]
WHOLE_RUNS = VARIANTS[:2]
DECISIONS = [("decision_accuracy_real", 3), ("decision_clutter_rejected", 3),
             ("decisions_resighting_elsewhere", 1), ("decisions_resighting_unassigned", 1),
             ("decisions_first_sighting_forced", 1)]


def decisions_table(families, folders, independent=2, joint=3):
    """One row per family: each decision metric's mean over the family's logs, independent → joint (variants
    `independent` and `joint` of `folders`)."""
    lines = ["| family | " + " | ".join(f"`{key}`" for key, _ in DECISIONS) + " |", "|---|" + "---|" * len(DECISIONS)]
    for family, (_, logs) in families.items():
        cells = []
        for key, digits in DECISIONS:
            before = [read_metrics(folders[(family, name, independent)]).get(key) for name, _ in logs]
            after = [read_metrics(folders[(family, name, joint)]).get(key) for name, _ in logs]
            cells.append(f"{mean_cell(before, digits)} → {mean_cell(after, digits)}")
        lines.append(f"| {family} | " + " | ".join(cells) + " |")
    return lines


def split_counts(variant_folders):
    """The cell "loop-closure splits, independent / joint" (branches.csv rows, summed over the family's runs)."""
    return " / ".join(str(sum(kept_counts(folder)[0] for folder in variant)) for variant in variant_folders)


def assignment_score_section(semslam, data, scratch, shown):
    lines = ["## The joint assignment score: joint compatibility (issue 10)", ""]
    runs = compare_variants(semslam, data, os.path.join(scratch, "assignment-score"), VARIANTS, "a")
    if runs is None:
        return lines + [NO_LOGS, ""]
    families, folders = runs
    lines += ["Whole runs: `mm-nh` with `--assignment-score independent` and with its defaults (the joint score) "
              "(docs/association-front-end.md §4, \"Joint compatibility\"). MRCLAM: mean `da_accuracy_real` over "
              "robots 1-5 × label seeds 1-3; KITTI tracking: mean `da_accuracy_real` / mean "
              "`clutter_rejected_moving` over 0000-0010; Lost in the Woods: `da_accuracy_real` / ATE [m]; KITTI 00 "
              "and 07: seeds within 2 × `known` association's ATE on the same log, mean ATE [m]. *up / down*: logs "
              "where the joint score's figure is better / worse. *time*: the sum of the runs' `time_s`, on a "
              "machine shared with the other runs of the section.", ""]
    lines += comparison_table(families, folders, variants=WHOLE_RUNS, times_header="independent / joint",
                              counts_header="loop-closure splits, independent / joint", counts=split_counts)
    lines += ["", "Decisions on the true history (`--on-true-history`: the graph follows the true association and "
              "each step's decision is recorded, never applied; docs/metrics.md), independent → joint, means over "
              "each family's logs (the counts per run):", ""]
    lines += decisions_table(families, folders)
    lines += ["", "```sh",
              shown([semslam, "run", "--method", "mm-nh", "--in", "LOG", "--out", "DIR", "--no-covariances",
                     "[--assignment-score independent]", "[--on-true-history]"]),
              "```",
              "LOG: as in the window sweep above.", ""]
    return lines
