"""docs/results.md section: the sweep behind the unassigned rule's defaults (docs/association-front-end.md §5 and
§1: μ the unassigned detections expected per step, M the confirmations, N the patience), on more than one log, so
that no default rests on one recording. Used by make_results.py.

One setting changes at a time from the defaults (μ = 1, M = 2, N = 10), `mm-nh`, on MRCLAM Dataset 6 robots 1-5
(whole recordings, 1 s keyframes, 3 classes, 10 % misclassification), Lost in the Woods (1 s keyframes, 3
classes, 10 %) and the KITTI 00 semantic simulation of the max-mixtures section (seed 1). Every cell comes from the
run's metrics.json; the commands are printed.
"""
import concurrent.futures
import os
import statistics

from results_commands import read_metrics, run_checked
from results_max_mixtures import kitti_simulation

# (flag, values); the default of each is in the list, so its row is the defaults' run.
SETTINGS = [("--unassigned-rate", ["0.1", "0.3", "1", "3"]),
            ("--confirmations", ["2", "3"]),
            ("--patience", ["5", "10", "20"])]
DEFAULTS = {"--unassigned-rate": "1", "--confirmations": "2", "--patience": "10"}
ROBOTS = [1, 2, 3, 4, 5]


def _logs(semslam, data, scratch):
    """(name, log path) of every log present; converted or simulated into `scratch`."""
    logs = []
    mrclam = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    if os.path.isdir(mrclam):
        for robot in ROBOTS:
            log = os.path.join(scratch, f"defaults_r{robot}.jsonl")
            run_checked([semslam, "convert", "mrclam", mrclam, "--out", log, "--robot", str(robot), "--classes", "3",
                  "--misclassification", "0.1", "--keyframe-period", "1"])
            logs.append((f"MRCLAM r{robot}", log))
    woods = os.path.join(data, "utias-lost-in-the-woods")
    if os.path.isdir(woods):
        log = os.path.join(scratch, "defaults_litw.jsonl")
        run_checked([semslam, "convert", "utias-lost-in-the-woods", woods, "--out", log, "--classes", "3",
              "--misclassification", "0.1", "--keyframe-period", "1"])
        logs.append(("Lost in the Woods", log))
    trajectory = os.path.join(data, "kitti-odometry-poses", "00.txt")
    if os.path.exists(trajectory):
        log = os.path.join(scratch, "defaults_kitti00.jsonl")
        run_checked(kitti_simulation(semslam, trajectory, log))
        logs.append(("KITTI 00", log))
    return logs


def _settings():
    """Every distinct setting: the defaults, then one flag changed at a time."""
    rows = [dict(DEFAULTS)]
    for flag, values in SETTINGS:
        for value in values:
            if value != DEFAULTS[flag]:
                rows.append(dict(DEFAULTS, **{flag: value}))
    return rows


def _label(setting):
    changed = [f"{flag} {value}" for flag, value in setting.items() if value != DEFAULTS[flag]]
    return ", ".join(changed) if changed else "defaults (μ 1, M 2, N 10)"


def association_defaults_section(semslam, data, scratch):
    lines = ["## The unassigned rule's defaults: μ, M and N swept on more than one log (issue 10)", ""]
    logs = _logs(semslam, data, scratch)
    if not logs:
        return lines + ["None of MRCLAM, Lost in the Woods or the KITTI odometry poses is present: section skipped.",
                        ""]
    settings = _settings()
    jobs = []
    for s, setting in enumerate(settings):
        for l, (name, log) in enumerate(logs):
            out = os.path.join(scratch, f"defaults_{s}_{l}")
            flags = [item for pair in setting.items() for item in pair]
            jobs.append((s, name, out, [semslam, "run", "--overwrite", "--method", "mm-nh", "--in", log, "--out", out,
                                        "--no-covariances"] + flags))
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, (os.cpu_count() or 2))) as pool:
        list(pool.map(lambda job: run_checked(job[3]), jobs))
    names = [name for name, _ in logs]
    mrclam = [name for name in names if name.startswith("MRCLAM")]
    lines += ["`mm-nh`, one setting changed at a time from the defaults. Cells: `da_accuracy_real` / ATE [m]; "
              "`MRCLAM mean` is the mean `da_accuracy_real` over the robots present.", "",
              "| setting | " + " | ".join(names) + (" | MRCLAM mean |" if mrclam else " |"),
              "|---|" + "---|" * (len(names) + (1 if mrclam else 0))]
    for s, setting in enumerate(settings):
        cells, accuracies = [], []
        for name in names:
            job = next(j for j in jobs if j[0] == s and j[1] == name)
            m = read_metrics(job[2])
            cells.append(f"{m['da_accuracy_real']:.3f} / {m['ate_rmse']:.3f}")
            if name in mrclam:
                accuracies.append(m["da_accuracy_real"])
        mean = f" {statistics.fmean(accuracies):.3f} |" if accuracies else ""
        lines.append(f"| {_label(setting)} | " + " | ".join(cells) + " |" + mean)
    lines += ["", "```sh",
              "build/bin/semslam run --method mm-nh --in LOG --out DIR --no-covariances "
              "[--unassigned-rate MU] [--confirmations M] [--patience N]",
              "```",
              "LOG: the MRCLAM and Lost in the Woods conversions of the association section and docs/datasets.md "
              "(3 classes, 10 %, 1 s keyframes), and the KITTI 00 simulation of the max-mixtures section.", ""]
    return lines
