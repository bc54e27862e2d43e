"""docs/results.md section `association-oracles` (issue 10): where mm-nh's association loss on MRCLAM Dataset 6 comes
from. Each robot's log (whole recording, 1 s keyframes, 3 classes, 10 % misclassification, label seeds 1-3) is run
as recorded and with one or both of two sources of difficulty removed by an oracle edit (python/oracle_logs.py):
the other robots' detections (clutter), and the odometry's error (each increment replaced by the true relative
motion, its stated covariance kept). The ceiling row pins the poses to the known-DA estimate
(`--on-known-trajectory`, as the association section does). Every figure of the table comes from a run's
metrics.json; cells are means over the three label seeds. Below it, the random-walk evidence of every landmark of the
runs as recorded (python/landmark_motion_evidence.py, through the Python module the build made).
"""
import concurrent.futures
import os
import sys

import oracle_logs
from results_commands import cell, mean_cell, read_metrics, run_checked

ROBOTS = [1, 2, 3, 4, 5]
SEEDS = [1, 2, 3]
# (label, oracle edits, extra run arguments)
VARIANTS = [
    ("as recorded", {}, []),
    ("clutter removed", {"drop_clutter": True}, []),
    ("odometry from the truth", {"true_odometry": True}, []),
    ("clutter removed, odometry from the truth", {"drop_clutter": True, "true_odometry": True}, []),
    ("ceiling: poses pinned to the known-DA estimate", {}, ["--on-known-trajectory"]),
]
MOTION_EVIDENCE_Q = 0.005  # m²/s, python/landmark_motion_evidence.py's default
KEYS = ["da_accuracy_real", "ate_rmse", "clutter_rejected", "landmarks_split", "landmarks_merged",
        "landmarks_estimated"]


def table(results):
    """Rows per variant: `da_accuracy_real` per robot (mean over its seeds) and over every run, and the other
    figures' means over every run, from {(variant label, robot, seed): metrics}."""
    lines = ["| variant | " + " | ".join(f"robot {r}" for r in ROBOTS) + " | mean | ATE mean [m] | clutter rejected "
             "mean | split / merged (mean) | landmarks (true 15, mean) |",
             "|---|" + "---|" * len(ROBOTS) + "---|---|---|---|---|"]
    for label, _, _ in VARIANTS:
        runs = [metrics for key, metrics in results.items() if key[0] == label]
        if not runs:
            continue
        per_robot = [mean_cell([results[(label, r, s)]["da_accuracy_real"] for s in SEEDS if (label, r, s) in results])
                     for r in ROBOTS]
        means = {key: [m.get(key) for m in runs] for key in KEYS}
        lines.append(f"| {label} | " + " | ".join(per_robot) + f" | {mean_cell(means['da_accuracy_real'])} | "
                     f"{mean_cell(means['ate_rmse'])} | {mean_cell(means['clutter_rejected'])} | "
                     f"{mean_cell(means['landmarks_split'], 1)} / {mean_cell(means['landmarks_merged'], 1)} | "
                     f"{mean_cell(means['landmarks_estimated'], 1)} |")
    return lines


def add_summaries(summaries):
    """One summary from several of landmark_motion_evidence.summary's: per group, counts and threshold counts
    summed, the largest Δ kept; groups in first-seen order."""
    total = {}
    for summary in summaries:
        for group, count, above, largest in summary:
            if group not in total:
                total[group] = [0, [0] * len(above), None]
            entry = total[group]
            entry[0] += count
            entry[1] = [a + b for a, b in zip(entry[1], above)]
            if largest is not None:
                entry[2] = largest if entry[2] is None else max(entry[2], largest)
    return [(group, count, above, largest) for group, (count, above, largest) in total.items()]


def motion_evidence_lines(semslam, runs):
    """The random-walk evidence (python/landmark_motion_evidence.py) over `runs`, [(log, run folder)], summed by
    group; needs the Python module the build made next to the tool (build/python)."""
    module_folder = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(semslam))), "python")
    if module_folder not in sys.path:
        sys.path.insert(0, module_folder)
    try:
        import landmark_motion_evidence
    except ImportError as error:
        return [f"The random-walk evidence needs the Python module in {module_folder} ({error}): skipped.", ""]
    summaries = []
    for log, run in runs:
        header, steps, poses, landmarks, detections = landmark_motion_evidence.read_run(log, run)
        evidence = landmark_motion_evidence.random_walk_evidence(header, steps, poses, landmarks, detections,
                                                                 MOTION_EVIDENCE_Q)
        summaries.append(landmark_motion_evidence.summary(evidence, detections))
    lines = ["**Is a landmark one static object?** (docs/association-front-end.md §9, \"The lead\"): per landmark of "
             f"the {len(runs)} runs as recorded, Δ = ln p(random walk) − ln p(static point), the landmark's "
             f"detections as a random walk of intensity q = {MOTION_EVIDENCE_Q} m²/s against one static point, the "
             "whole graph of the run's final associations re-solved, compared by Laplace evidence "
             "(`python/landmark_motion_evidence.py`). Landmarks grouped by the truth of their detections:", "",
             "| landmarks | count | Δ > 0 | Δ > 5 | Δ > 10 | largest Δ |", "|---|---|---|---|---|---|"]
    for group, count, above, largest in add_summaries(summaries):
        lines.append(f"| {group} | {count} | " + " | ".join(str(a) for a in above) + f" | {cell(largest, 1)} |")
    return lines + ["", "```sh", "PYTHONPATH=build/python /usr/bin/python3 python/landmark_motion_evidence.py "
                    "rN-sS.jsonl DIR   # DIR: the run of the log as recorded", "```", ""]


def association_oracles_section(semslam, data, scratch, shown):
    folder = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    lines = ["## Where MRCLAM's association loss comes from (issue 10)", ""]
    if not os.path.isdir(folder):
        return lines + [f"MRCLAM Dataset 6 is not at {folder}: section skipped.", ""]
    scratch = os.path.join(scratch, "association-oracles")
    os.makedirs(scratch, exist_ok=True)

    def convert(robot, seed):
        return [semslam, "convert", "mrclam", folder, "--robot", str(robot), "--keyframe-period", "1", "--classes",
                "3", "--misclassification", "0.1", "--seed", str(seed)]

    recorded = {(r, s): os.path.join(scratch, f"r{r}-s{s}.jsonl") for r in ROBOTS for s in SEEDS}
    jobs = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(lambda item: run_checked(convert(*item[0]) + ["--out", item[1]]), recorded.items()))
        for label_index, (label, edits, arguments) in enumerate(VARIANTS):
            for (r, s), path in recorded.items():
                log = path
                if edits:
                    log = os.path.join(scratch, f"r{r}-s{s}-v{label_index}.jsonl")
                    oracle_logs.edit(path, log, **edits)
                jobs.append((label, r, s, log, os.path.join(scratch, f"r{r}-s{s}-v{label_index}"), arguments))
        list(pool.map(lambda job: run_checked(
            [semslam, "run", "--overwrite", "--quiet", "--method", "mm-nh", "--in", job[3], "--out", job[4],
             "--no-covariances"] + job[5]), jobs))
    results = {(label, r, s): read_metrics(out) for label, r, s, _, out, _ in jobs}
    lines += ["mm-nh with its defaults on each robot's whole recording (1 s keyframes, 3 classes, 10 % "
              "misclassification), as recorded and with oracle edits that remove one source of difficulty using "
              "the log's truth (python/oracle_logs.py; diagnostics, never an estimator's input): the other robots' "
              "detections (`--drop-clutter`), and the odometry's error (`--true-odometry`: each increment between "
              "two steps with a true pose becomes the true relative motion, its stated covariance kept). The "
              "ceiling pins the poses to the known-DA estimate. Cells: `da_accuracy_real`, mean over label seeds "
              f"{SEEDS[0]}-{SEEDS[-1]}; the last columns are means over all {len(ROBOTS) * len(SEEDS)} runs.", ""]
    lines += table(results) + [""]
    lines += ["```sh", shown(convert(1, 1) + ["--out", "r1.jsonl"]).replace("--robot 1", "--robot N").replace(
        "--seed 1", "--seed S").replace("r1.jsonl", "rN-sS.jsonl"),
              "python3 python/oracle_logs.py rN-sS.jsonl edited.jsonl [--drop-clutter] [--true-odometry]",
              "build/bin/semslam run --method mm-nh --in edited.jsonl --out DIR --no-covariances",
              "build/bin/semslam run --method mm-nh --in rN-sS.jsonl --out DIR --no-covariances --on-known-trajectory",
              "```", ""]
    recorded_runs = [(log, out) for label, _, _, log, out, _ in jobs if label == VARIANTS[0][0]]
    return lines + motion_evidence_lines(semslam, recorded_runs)
