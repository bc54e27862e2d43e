"""docs/results.md section of issue 10's association front end (docs/association-front-end.md); used by
make_results.py.

MRCLAM Dataset 6, every robot, whole recording at 1 s keyframes: each method with the unassigned birth rule, paper
B's threshold rule for mm-nh, and the association ceiling (the same front end with the poses pinned to the known-DA
estimate, `--on-known-trajectory`). Every row comes from the run's metrics.json; the commands are printed.
"""
import concurrent.futures
import json
import os
import subprocess
import sys

ROBOTS = [1, 2, 3, 4, 5]
COLUMNS = ["ate_rmse", "da_accuracy_real", "pairwise_precision", "pairwise_recall", "clutter_rejected",
           "landmarks_merged", "landmarks_split", "landmarks_estimated", "time_s"]


def _run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"results_association.py: {' '.join(command)} failed:\n{result.stdout}{result.stderr}")


def _metrics(folder):
    with open(os.path.join(folder, "metrics.json")) as f:
        return json.load(f)


def _cell(value):
    if value is None:
        return "–"
    return f"{value:.3f}" if isinstance(value, float) else str(value)


# (label, method, extra arguments)
RUNS = [
    ("known", "known", []),
    ("ml", "ml", ["--birth", "unassigned"]),
    ("gpda", "gpda", ["--birth", "unassigned"]),
    ("mm", "mm", ["--birth", "unassigned"]),
    ("mm-nh", "mm-nh", ["--birth", "unassigned"]),
    ("mm-nh, threshold birth (paper B)", "mm-nh", ["--birth", "threshold"]),
    ("mm-nh ceiling (known-DA poses)", "mm-nh", ["--birth", "unassigned", "--on-known-trajectory"]),
]
VARIANTS = [
    ("3 classes, 10 % misclassification", ["--classes", "3", "--misclassification", "0.1"], RUNS),
    ("2 classes, 10 % misclassification (cluster members share classes)", ["--classes", "2", "--misclassification",
                                                                            "0.1"], [RUNS[0], RUNS[4], RUNS[6]]),
    ("3 classes, 0 % misclassification", ["--classes", "3", "--misclassification", "0"], [RUNS[0], RUNS[4], RUNS[6]]),
]


def association_section(semslam, data, scratch, shown):
    folder = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    lines = ["## Association on MRCLAM Dataset 6, every robot (issue 10)", ""]
    if not os.path.isdir(folder):
        return lines + [f"MRCLAM Dataset 6 is not at {folder}: section skipped.", ""]
    lines += ["Whole recordings at 1 s keyframes; the unassigned birth rule with provisional landmarks "
              "(docs/association-front-end.md); `ceiling`: mm-nh's front end with the poses pinned to the known-DA "
              "estimate (`--on-known-trajectory`), what association alone reaches there. Clutter is the other robots "
              "(uniform labels).", ""]
    jobs = []
    for v, (title, convert_args, runs) in enumerate(VARIANTS):
        for robot in ROBOTS:
            log = os.path.join(scratch, f"association_v{v}_r{robot}.jsonl")
            jobs.append((v, robot, log, convert_args, runs))
    commands_shown = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, (os.cpu_count() or 2))) as pool:
        list(pool.map(lambda job: _run([semslam, "convert", "mrclam", folder, "--out", job[2], "--robot",
                                        str(job[1]), "--keyframe-period", "1"] + job[3]), jobs))
        tasks = []
        for v, robot, log, convert_args, runs in jobs:
            for r, (label, method, extra) in enumerate(runs):
                out = os.path.join(scratch, f"association_v{v}_r{robot}_{r}")
                command = [semslam, "run", "--method", method, "--in", log, "--out", out, "--no-covariances"] + extra
                tasks.append((v, robot, label, out, command))
        list(pool.map(lambda task: _run(task[4]), tasks))
    for v, (title, convert_args, runs) in enumerate(VARIANTS):
        lines += [f"### {title}", "",
                  "| robot | method | ATE [m] | da_accuracy_real | pairwise precision | pairwise recall | "
                  "clutter rejected | merged | split | landmarks (true 15) | time [s] |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for task in tasks:
            if task[0] != v:
                continue
            m = _metrics(task[3])
            lines.append(f"| {task[1]} | {task[2]} | " + " | ".join(_cell(m.get(c)) for c in COLUMNS) + " |")
        lines.append("")
        commands_shown.append(shown([semslam, "convert", "mrclam", folder, "--out", "rN.jsonl", "--robot", "N",
                                     "--keyframe-period", "1"] + convert_args))
    lines += ["```sh"] + commands_shown + [
        "build/bin/semslam run --method M --in rN.jsonl --out DIR --no-covariances --birth unassigned",
        "build/bin/semslam run --method mm-nh --in rN.jsonl --out DIR --no-covariances --birth threshold",
        "build/bin/semslam run --method mm-nh --in rN.jsonl --out DIR --no-covariances --birth unassigned "
        "--on-known-trajectory",
        "```", ""]
    return lines
