"""docs/results.md section `association-oracles` (issue 10): where mm-nh's association loss on MRCLAM Dataset 6 comes
from. Each robot's log (whole recording, 1 s keyframes, 3 classes, 10 % misclassification, label seeds 1-3) is run
as recorded and with one or both of two sources of difficulty removed by an oracle edit (python/oracle_logs.py):
the other robots' detections (clutter), and the odometry's error (each increment replaced by the true relative
motion, its stated covariance kept). The ceiling row pins the poses to the known-DA estimate
(`--on-known-trajectory`, as the association section does). Every figure of the table comes from a run's
metrics.json; cells are means over the three label seeds. A third edit removes only the odometry's slowly varying
error (its error averaged over a minute around each step, `odometry_bias_window`): what a bias state could at best
give. Below it, the random-walk evidence of every landmark of the runs as recorded (python/landmark_motion_evidence.py,
through the Python module the build made), and what dropping the detections of the landmarks it flags would give at
best (the log without them, re-run; a real detection dropped counts as wrong).
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
    ("odometry bias removed (its error averaged over 60 s)", {"odometry_bias_window": 60.0}, []),
    ("clutter removed, odometry from the truth", {"drop_clutter": True, "true_odometry": True}, []),
    ("ceiling: poses pinned to the known-DA estimate", {}, ["--on-known-trajectory"]),
]
MOTION_EVIDENCE_Q = 0.005  # m²/s, python/landmark_motion_evidence.py's default
FLAG_THRESHOLDS = [5.0, 10.0]  # Δ above which a landmark's detections are dropped, one table row each
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


def import_motion_evidence(semslam):
    """The landmark_motion_evidence module with the Python module the build made next to the tool (build/python)
    on the path, or the ImportError's text."""
    module_folder = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(semslam))), "python")
    if module_folder not in sys.path:
        sys.path.insert(0, module_folder)
    try:
        import landmark_motion_evidence
    except ImportError as error:
        return None, f"The random-walk evidence needs the Python module in {module_folder} ({error}): skipped."
    return landmark_motion_evidence, None


def motion_evidence_lines(module, evidence_of_runs):
    """The random-walk evidence (python/landmark_motion_evidence.py) of every run, [(evidence, detections)],
    summed by group."""
    summaries = [module.summary(evidence, detections) for evidence, detections in evidence_of_runs]
    lines = ["**Is a landmark one static object?** (docs/association-front-end.md §9, \"The lead\"): per landmark of "
             f"the {len(evidence_of_runs)} runs as recorded, Δ = ln p(random walk) − ln p(static point), the "
             f"landmark's detections as a random walk of intensity q = {MOTION_EVIDENCE_Q} m²/s against one static "
             "point, the whole graph of the run's final associations re-solved, compared by Laplace evidence "
             "(`python/landmark_motion_evidence.py`). Landmarks grouped by the truth of their detections:", "",
             "| landmarks | count | Δ > 0 | Δ > 5 | Δ > 10 | largest Δ |", "|---|---|---|---|---|---|"]
    for group, count, above, largest in add_summaries(summaries):
        lines.append(f"| {group} | {count} | " + " | ".join(str(a) for a in above) + f" | {cell(largest, 1)} |")
    return lines + ["", "```sh", "PYTHONPATH=build/python /usr/bin/python3 python/landmark_motion_evidence.py "
                    "rN-sS.jsonl DIR   # DIR: the run of the log as recorded", "```", ""]


def accuracy_with_dropped_as_wrong(metrics, real_dropped):
    """`da_accuracy_real` of a run on a log without some real detections, those counted as wrong (a demoted
    landmark leaves its detections on no landmark): correct / (real detections left + real ones dropped)."""
    real_left = metrics["da_total"] - metrics["da_clutter"]
    if real_left + real_dropped == 0:
        return None
    return metrics["da_accuracy_real"] * real_left / (real_left + real_dropped)


def real_detections_on(detections, flagged):
    """How many detections of landmark_motion_evidence.read_run's list on a landmark in `flagged` are of a true
    landmark (truth neither clutter, `unknown` nor missing)."""
    return sum(1 for d in detections if d[1] in flagged and d[5] not in ("not-a-landmark", "unknown", ""))


def demotion_lines(semslam, module, recorded, evidence_of_runs, recorded_metrics):
    """For each threshold, every run's log without the detections its run left on a landmark whose Δ exceeds it,
    run again: an optimistic estimate of demoting flagged landmarks online (they would be found later, not at
    birth)."""
    jobs = []
    for threshold in FLAG_THRESHOLDS:
        for (log, run), (evidence, detections) in zip(recorded, evidence_of_runs):
            flagged = {landmark for landmark, delta in evidence.items() if delta > threshold}
            edited = f"{run}-without-above-{threshold:g}.jsonl"
            counts = oracle_logs.edit(log, edited, drop_detections=module.detections_on(detections, flagged))
            real = real_detections_on(detections, flagged)
            jobs.append((threshold, edited, edited[:-len(".jsonl")], real, counts["detections_dropped"] - real))
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(lambda job: run_checked([semslam, "run", "--overwrite", "--quiet", "--method", "mm-nh", "--in",
                                               job[1], "--out", job[2], "--no-covariances"]), jobs))
    lines = ["**Dropping what the evidence flags, at best**: each run's log without the detections the run left on a "
             "landmark whose Δ exceeds the threshold, run again (`--write-without-flagged`); `da_accuracy_real` "
             "counts a dropped real detection as wrong (a demoted landmark leaves it on no landmark), the next "
             "column leaves them out. Online, a landmark would be flagged only after its detections had pulled the "
             "poses, so this is an optimistic estimate of a demotion rule (not a strict bound: each run is "
             f"path-dependent). Means over the {len(recorded)} runs.", "",
             "| detections dropped from landmarks with | da_accuracy_real | on the detections left | ATE [m] | "
             "clutter / real detections dropped (sum) |", "|---|---|---|---|---|",
             f"| none (as recorded) | {mean_cell([m['da_accuracy_real'] for m in recorded_metrics])} | – | "
             f"{mean_cell([m['ate_rmse'] for m in recorded_metrics])} | 0 / 0 |"]
    for threshold in FLAG_THRESHOLDS:
        rows = [(read_metrics(out), real, clutter) for t, _, out, real, clutter in jobs if t == threshold]
        lines.append(f"| Δ > {threshold:g} | "
                     f"{mean_cell([accuracy_with_dropped_as_wrong(m, real) for m, real, _ in rows])} | "
                     f"{mean_cell([m['da_accuracy_real'] for m, _, _ in rows])} | "
                     f"{mean_cell([m['ate_rmse'] for m, _, _ in rows])} | "
                     f"{sum(c for _, _, c in rows)} / {sum(r for _, r, _ in rows)} |")
    return lines + ["", "```sh", "PYTHONPATH=build/python /usr/bin/python3 python/landmark_motion_evidence.py "
                    "rN-sS.jsonl DIR --write-without-flagged edited.jsonl --above 5",
                    "build/bin/semslam run --method mm-nh --in edited.jsonl --out DIR2 --no-covariances", "```", ""]


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
              "two steps with a true pose becomes the true relative motion, its stated covariance kept; "
              "`--odometry-bias-from-truth 60`: only its slowly varying part, each increment's error rate averaged "
              "over the steps within 30 s, removed: what a bias state could at best give). The "
              "ceiling pins the poses to the known-DA estimate. Cells: `da_accuracy_real`, mean over label seeds "
              f"{SEEDS[0]}-{SEEDS[-1]}; the last columns are means over all {len(ROBOTS) * len(SEEDS)} runs.", ""]
    lines += table(results) + [""]
    lines += ["```sh", shown(convert(1, 1) + ["--out", "r1.jsonl"]).replace("--robot 1", "--robot N").replace(
        "--seed 1", "--seed S").replace("r1.jsonl", "rN-sS.jsonl"),
              "python3 python/oracle_logs.py rN-sS.jsonl edited.jsonl [--drop-clutter] [--true-odometry] "
              "[--odometry-bias-from-truth 60]",
              "build/bin/semslam run --method mm-nh --in edited.jsonl --out DIR --no-covariances",
              "build/bin/semslam run --method mm-nh --in rN-sS.jsonl --out DIR --no-covariances --on-known-trajectory",
              "```", ""]
    recorded_runs = [(log, out) for label, _, _, log, out, _ in jobs if label == VARIANTS[0][0]]
    module, missing = import_motion_evidence(semslam)
    if module is None:
        return lines + [missing, ""]
    evidence_of_runs = []
    for log, run in recorded_runs:
        header, steps, poses, landmarks, detections = module.read_run(log, run)
        evidence_of_runs.append((module.random_walk_evidence(header, steps, poses, landmarks, detections,
                                                             MOTION_EVIDENCE_Q), detections))
    recorded_metrics = [read_metrics(run) for _, run in recorded_runs]
    return (lines + motion_evidence_lines(module, evidence_of_runs) +
            demotion_lines(semslam, module, recorded_runs, evidence_of_runs, recorded_metrics))
