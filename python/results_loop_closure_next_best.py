"""docs/results.md section `loop-closure-next-best`: the third branch at an ambiguous loop closure (mm-nh's default
since session 20; docs/association-front-end.md §10), in which the anchoring detections take their next-best
landmarks, against two branches (`--no-loop-closure-next-best`), on every log family of the window sweep
(results_loop_closure_branches.py: MRCLAM Dataset 6 robots 1-5 × label seeds 1-3, KITTI tracking 0000-0010 at 1 Hz ×5,
Lost in the Woods, the KITTI 00 and 07 simulations with seeds 1-8) and on MRCLAM with 2 classes and with 0 %
misclassification (robots 1-5, label seed 1). `mm-nh` with its defaults (W = 16, three branches) and with the third
branch turned off; every cell comes from the runs' metrics.json and branches.csv. Used by make_results.py.
"""
import concurrent.futures
import os

from results_commands import read_metrics, run_checked
from results_loop_closure_branches import NO_LOGS, ROBOTS, compare_variants, family_figure

VARIANTS = [("two branches", ["--no-loop-closure-next-best"]), ("with the third branch (the default)", [])]
EXTRA_MRCLAM = [("MRCLAM, 2 classes", ["--classes", "2", "--misclassification", "0.1"]),
                ("MRCLAM, 0 %", ["--classes", "3", "--misclassification", "0"])]


def extra_mrclam_logs(semslam, data, scratch):
    """{family: ("mrclam", [(name, log)])} for EXTRA_MRCLAM (label seed 1), converted into `scratch`."""
    folder = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    if not os.path.isdir(folder):
        return {}
    families, jobs = {}, []
    for index, (family, arguments) in enumerate(EXTRA_MRCLAM):
        logs = []
        for robot in ROBOTS:
            log = os.path.join(scratch, f"next_best_m{index}_r{robot}.jsonl")
            jobs.append([semslam, "convert", "mrclam", folder, "--out", log, "--robot", str(robot),
                         "--keyframe-period", "1"] + arguments)
            logs.append((f"r{robot}", log))
        families[family] = ("mrclam", logs)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, os.cpu_count() or 2)) as pool:
        list(pool.map(run_checked, jobs))
    return families


def kept_counts(folder):
    """(splits, splits that opened the third branch, splits that kept it) from a run folder's branches.csv (none
    written: no split)."""
    path = os.path.join(folder, "branches.csv")
    if not os.path.exists(path):
        return 0, 0, 0
    with open(path) as f:
        rows = [row.split(",") for row in f.read().splitlines()[1:]]
    return len(rows), sum(1 for row in rows if row[4] != ""), sum(1 for row in rows if row[5] == "next-best")


def paired_changes(kind, before, after):
    """`up / down`: logs where the figure `after` is higher / lower than `before` (`da_accuracy_real` for the real
    logs, lower ATE counting as up for the simulations); logs where it is undefined are left out."""
    key = "ate_rmse" if kind == "simulation" else "da_accuracy_real"
    sign = -1.0 if kind == "simulation" else 1.0
    pairs = [(b.get(key), a.get(key)) for b, a in zip(before, after)]
    pairs = [(b, a) for b, a in pairs if isinstance(b, (int, float)) and isinstance(a, (int, float))]
    return f"{sum(1 for b, a in pairs if sign * (a - b) > 0)} / {sum(1 for b, a in pairs if sign * (a - b) < 0)}"


def third_branch_counts(variant_folders):
    """The cell "splits / third branch opened / kept" of the last variant's runs (one folder list per variant)."""
    counts = [kept_counts(folder) for folder in variant_folders[-1]]
    return " / ".join(str(sum(c[i] for c in counts)) for i in range(3))


def comparison_table(families, folders, variants=VARIANTS, times_header="two / three branches",
                     counts_header="splits / third branch opened / kept", counts=third_branch_counts):
    """One row per family: each variant's figure, the paired up / down count (last variant against the first),
    every variant's total `time_s`, and the cell `counts` makes from the runs' folders (one list per variant)."""
    lines = ["| family | " + " | ".join(label for label, _ in variants) + " | up / down | time [s] (sum, "
             f"{times_header}) | {counts_header} |", "|---|" + "---|" * (len(variants) + 3)]
    for family, (kind, logs) in families.items():
        variant_folders = [[folders[(family, name, index)] for name, _ in logs] for index in range(len(variants))]
        runs = [[read_metrics(folder) for folder in variant] for variant in variant_folders]
        known = ([read_metrics(folders[(family, name, "known")])["ate_rmse"] for name, _ in logs]
                 if kind == "simulation" else None)
        times = " / ".join(f"{sum(m['time_s'] for m in variant):.1f}" for variant in runs)
        lines.append(f"| {family} | " + " | ".join(family_figure(kind, variant, known) for variant in runs) +
                     f" | {paired_changes(kind, runs[0], runs[-1])} | {times} | {counts(variant_folders)} |")
    return lines


def loop_closure_next_best_section(semslam, data, scratch, shown):
    lines = ["## The third branch at an ambiguous loop closure: the next-best landmarks (issue 10)", ""]
    runs = compare_variants(semslam, data, os.path.join(scratch, "loop-closure-next-best"), VARIANTS, "v",
                            extra_mrclam_logs)
    if runs is None:
        return lines + [NO_LOGS, ""]
    families, folders = runs
    lines += ["`mm-nh` with its defaults (W = 16 and a third branch in which the anchoring detections take their "
              "next-best landmarks; docs/association-front-end.md §10) and with `--no-loop-closure-next-best` (two "
              "branches). "
              "MRCLAM: mean `da_accuracy_real` (robots 1-5 × label seeds 1-3 at 3 classes and 10 %; robots 1-5, label "
              "seed 1, in the other two rows); KITTI tracking: mean `da_accuracy_real` / mean "
              "`clutter_rejected_moving` over 0000-0010; Lost in the Woods: `da_accuracy_real` / ATE [m]; KITTI 00 "
              "and 07: seeds within 2 × `known` association's ATE on the same log, mean ATE [m]. *up / down*: logs "
              "where the third branch's figure is better / worse (`da_accuracy_real`; ATE for the simulations). "
              "*time*: the sum of the runs' `time_s`, on a machine shared with the other runs of the section.", ""]
    lines += comparison_table(families, folders)
    lines += ["", "```sh",
              shown([semslam, "run", "--method", "mm-nh", "--in", "LOG", "--out", "DIR", "--no-covariances",
                     "[--no-loop-closure-next-best]"]),
              "```",
              "LOG: as in the window sweep above; MRCLAM with 2 classes: `semslam convert mrclam "
              "../shared/data/mrclam/MRCLAM_Dataset6 --robot N --keyframe-period 1 --classes 2 --misclassification "
              "0.1`, with 0 %: `--classes 3 --misclassification 0`.", ""]
    return lines
