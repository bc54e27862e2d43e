"""docs/results.md section: the sweep behind the unassigned rule's defaults (docs/association-front-end.md §5 and
§1: μ the unassigned detections expected per step, M the confirmations, Δt their spacing in seconds, the viewpoint
rule, N the patience), on more than one log, so that no default rests on one recording. Used by make_results.py.

One setting changes at a time from the defaults (μ = 1, M = 2, Δt = 1 s, no viewpoint rule, N = 10), `mm-nh`, on
MRCLAM Dataset 6 robots 1-5 (whole recordings, 1 s keyframes, 3 classes, 10 % misclassification), Lost in the Woods
(1 s keyframes, 3 classes, 10 %), the KITTI 00 semantic simulation of the max-mixtures section (seed 1), and real
detector output: KITTI tracking 0000-0010 at 1 Hz keyframes with noisy odometry ×5 (the issue's read-out
configuration, seed 1) and 0000 and 0005 at the native 10 Hz with ORB-SLAM3 odometry (the spacing is in seconds so
that it means the same at both rates). Every cell comes from the run's metrics.json; the commands are printed.
"""
import concurrent.futures
import os

from results_commands import mean_cell, read_metrics, run_checked
from results_max_mixtures import kitti_simulation

# (flag, values); the default of each is in the list, so its row is the defaults' run.
SETTINGS = [("--unassigned-rate", ["0.1", "0.3", "1", "3"]),
            ("--confirmations", ["2", "3"]),
            ("--confirmation-spacing", ["0.5", "1", "3"]),
            ("--confirmation-viewpoint-sigmas", ["0", "1", "2"]),
            ("--patience", ["5", "10", "20"])]
DEFAULTS = {"--unassigned-rate": "1", "--confirmations": "2", "--confirmation-spacing": "1",
            "--confirmation-viewpoint-sigmas": "0", "--patience": "10"}
ROBOTS = [1, 2, 3, 4, 5]
TRACKING_SEQUENCES = range(11)
TRACKING_10HZ = [0, 5]


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
    tracking = os.path.join(data, "kitti-tracking")
    if os.path.isdir(tracking):
        for sequence in TRACKING_SEQUENCES:
            log = os.path.join(scratch, f"defaults_tracking{sequence:04d}_1hz.jsonl")
            run_checked([semslam, "convert", "kitti-tracking", tracking, "--sequence", str(sequence),
                         "--keyframe-period", "1", "--odometry", "noisy", "--odom-noise-scale", "5", "--seed", "1",
                         "--out", log])
            logs.append((f"KITTI tracking {sequence:04d} 1 Hz", log))
        for sequence in TRACKING_10HZ:
            log = os.path.join(scratch, f"defaults_tracking{sequence:04d}_10hz.jsonl")
            run_checked([semslam, "convert", "kitti-tracking", tracking, "--sequence", str(sequence), "--odometry",
                         "orbslam", "--out", log])
            logs.append((f"KITTI tracking {sequence:04d} 10 Hz", log))
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
    return ", ".join(changed) if changed else "defaults (μ 1, M 2, Δt 1 s, no viewpoint rule, N 10)"


def association_defaults_section(semslam, data, scratch):
    lines = ["## The unassigned rule's defaults: μ, M, Δt, the viewpoint rule and N swept on more than one log "
             "(issues 10, 11)", ""]
    logs = _logs(semslam, data, scratch)
    if not logs:
        return lines + ["None of MRCLAM, Lost in the Woods, the KITTI odometry poses or KITTI tracking is present: "
                        "section skipped.", ""]
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
    single = [name for name in names if not name.startswith("KITTI tracking")]
    mrclam = [name for name in names if name.startswith("MRCLAM")]
    groups = [(title, [name for name in names if name.startswith("KITTI tracking") and name.endswith(rate)])
              for title, rate in (("KITTI tracking 1 Hz ×5", "1 Hz"), ("KITTI tracking 10 Hz", "10 Hz"))]
    groups = [(title, members) for title, members in groups if members]
    header = single + (["MRCLAM mean"] if mrclam else []) + [f"{title} ({len(members)} seq.)"
                                                             for title, members in groups]
    lines += ["`mm-nh`, one setting changed at a time from the defaults. Cells: `da_accuracy_real` / ATE [m] on "
              "MRCLAM, Lost in the Woods and KITTI 00; `MRCLAM mean`: mean `da_accuracy_real` / mean "
              "`clutter_rejected` over the robots; KITTI tracking: mean `da_accuracy_real` / mean "
              "`clutter_rejected_moving` / mean `clutter_rejected_false_positive` over the sequences (a count in "
              "brackets where a metric is undefined on some: 0006 has no static landmark).", "",
              "| setting | " + " | ".join(header) + " |", "|---|" + "---|" * len(header)]

    def metrics(s, name):
        job = next(j for j in jobs if j[0] == s and j[1] == name)
        return read_metrics(job[2])

    for s, setting in enumerate(settings):
        cells = []
        for name in single:
            m = metrics(s, name)
            cells.append(f"{m['da_accuracy_real']:.3f} / {m['ate_rmse']:.3f}")
        if mrclam:
            runs = [metrics(s, name) for name in mrclam]
            cells.append(mean_cell([m["da_accuracy_real"] for m in runs]) + " / " +
                         mean_cell([m["clutter_rejected"] for m in runs], 2))
        for _, members in groups:
            runs = [metrics(s, name) for name in members]
            cells.append(" / ".join(mean_cell([m.get(key) for m in runs]) for key in
                                    ("da_accuracy_real", "clutter_rejected_moving", "clutter_rejected_false_positive")))
        lines.append(f"| {_label(setting)} | " + " | ".join(cells) + " |")
    lines += ["", "```sh",
              "build/bin/semslam run --method mm-nh --in LOG --out DIR --no-covariances "
              "[--unassigned-rate MU] [--confirmations M] [--confirmation-spacing SECONDS] "
              "[--confirmation-viewpoint-sigmas K] [--patience N]",
              "```",
              "LOG: the MRCLAM and Lost in the Woods conversions of the association section and docs/datasets.md "
              "(3 classes, 10 %, 1 s keyframes), the KITTI 00 simulation of the max-mixtures section, and the KITTI "
              "tracking conversions `semslam convert kitti-tracking ../shared/data/kitti-tracking --sequence N "
              "--keyframe-period 1 --odometry noisy --odom-noise-scale 5 --seed 1` (1 Hz) and `... --sequence N "
              "--odometry orbslam` (10 Hz).", ""]
    return lines
