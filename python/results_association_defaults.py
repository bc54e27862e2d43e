"""docs/results.md section: the sweep behind the unassigned rule's defaults (docs/association-front-end.md §5, §1
and §10: μ the unassigned detections expected per step, constant or estimated from the run with a prior weight of W
steps, M the confirmations, Δt their spacing in seconds, the viewpoint rule, N the patience), on more than one log, so
that no default rests on one recording. Used by make_results.py.

One setting changes at a time from the defaults (μ = 1 constant, M = 2, Δt = 1 s, no viewpoint rule, N = 10), `mm-nh`,
on MRCLAM Dataset 6 robots 1-5 each converted with label seeds 1-8 (whole recordings, 1 s keyframes, 3 classes, 10 %
misclassification: 40 runs, since one run's `da_accuracy_real` moves by ±0.05 with its path,
docs/association-front-end.md §9, and one seed per robot cannot rank settings), Lost in the Woods (1 s keyframes, 3
classes, 10 %), the KITTI 00 and 07 semantic simulations of the association section (seeds 1-8, against `known` on
the same logs), and real detector output: KITTI tracking 0000-0010 at 1 Hz keyframes with noisy odometry ×5 (the
issue's read-out configuration, seed 1) and 0000 and 0005 at the native 10 Hz with ORB-SLAM3 odometry (the spacing is
in seconds so that it means the same at both rates). Each MRCLAM row is paired with the defaults' runs of the same
logs (python/paired_runs.py's summary: the mean difference with its paired bootstrap interval, and on how many runs
it is higher and lower). Every cell comes from the runs' metrics.json; the commands are printed.
"""
import concurrent.futures
import os

from paired_runs import summary
from results_association import KITTI_LOGS
from results_commands import cell, mean_cell, read_metrics, run_checked
from results_max_mixtures import kitti_simulation

# (flag, values); the default of each is in the list, so its row is the defaults' run. None: the flag not given
# (--unassigned-rate-weight: μ constant unless it is).
SETTINGS = [("--unassigned-rate", ["0.1", "0.3", "1", "3"]),
            ("--unassigned-rate-weight", [None, "10", "100", "300"]),
            ("--confirmations", ["2", "3"]),
            ("--confirmation-spacing", ["0.5", "1", "3"]),
            ("--confirmation-viewpoint-sigmas", ["0", "1", "2"]),
            ("--patience", ["5", "10", "20"])]
DEFAULTS = {"--unassigned-rate": "1", "--unassigned-rate-weight": None, "--confirmations": "2",
            "--confirmation-spacing": "1", "--confirmation-viewpoint-sigmas": "0", "--patience": "10"}
ROBOTS = [1, 2, 3, 4, 5]
LABEL_SEEDS = range(1, 9)
TRACKING_SEQUENCES = range(11)
TRACKING_10HZ = [0, 5]


def _logs(semslam, data, scratch):
    """(family, name, log path) of every log present; converted or simulated into `scratch`. Families: "MRCLAM",
    "Lost in the Woods", "KITTI", "KITTI tracking 1 Hz", "KITTI tracking 10 Hz"."""
    def log(name):
        return os.path.join(scratch, f"defaults_{name}.jsonl")

    made = []  # (family, name, the command that writes log(name))
    mrclam = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    if os.path.isdir(mrclam):
        made += [("MRCLAM", f"r{robot}-s{seed}",
                  [semslam, "convert", "mrclam", mrclam, "--robot", str(robot), "--classes", "3",
                   "--misclassification", "0.1", "--keyframe-period", "1", "--seed", str(seed), "--out",
                   log(f"r{robot}-s{seed}")])
                 for robot in ROBOTS for seed in LABEL_SEEDS]
    woods = os.path.join(data, "utias-lost-in-the-woods")
    if os.path.isdir(woods):
        made.append(("Lost in the Woods", "litw", [semslam, "convert", "utias-lost-in-the-woods", woods, "--classes",
                                                   "3", "--misclassification", "0.1", "--keyframe-period", "1",
                                                   "--out", log("litw")]))
    for sequence, seed in KITTI_LOGS:
        trajectory = os.path.join(data, "kitti-odometry-poses", f"{sequence}.txt")
        if os.path.exists(trajectory):
            name = f"kitti{sequence}-seed{seed}"
            made.append(("KITTI", name, kitti_simulation(semslam, trajectory, log(name), seed)))
    tracking = os.path.join(data, "kitti-tracking")
    if os.path.isdir(tracking):
        made += [("KITTI tracking 1 Hz", f"tracking{sequence:04d}_1hz",
                  [semslam, "convert", "kitti-tracking", tracking, "--sequence", str(sequence), "--keyframe-period",
                   "1", "--odometry", "noisy", "--odom-noise-scale", "5", "--seed", "1", "--out",
                   log(f"tracking{sequence:04d}_1hz")])
                 for sequence in TRACKING_SEQUENCES]
        made += [("KITTI tracking 10 Hz", f"tracking{sequence:04d}_10hz",
                  [semslam, "convert", "kitti-tracking", tracking, "--sequence", str(sequence), "--odometry",
                   "orbslam", "--out", log(f"tracking{sequence:04d}_10hz")]) for sequence in TRACKING_10HZ]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, (os.cpu_count() or 2))) as pool:
        list(pool.map(lambda item: run_checked(item[2]), made))
    logs = [(family, name, log(name)) for family, name, _ in made]
    return logs


def _settings():
    """Every distinct setting: the defaults, then one flag changed at a time."""
    rows = [dict(DEFAULTS)]
    for flag, values in SETTINGS:
        for value in values:
            if value != DEFAULTS[flag]:
                rows.append(dict(DEFAULTS, **{flag: value}))
    return rows


def setting_flags(setting):
    """The command-line flags of a setting: each flag with its value, a flag whose value is None left out."""
    return [item for flag, value in setting.items() if value is not None for item in (flag, value)]


def _label(setting):
    changed = [f"{flag} {value}" for flag, value in setting.items() if value != DEFAULTS[flag]]
    return ", ".join(changed) if changed else "defaults (μ 1 constant, M 2, Δt 1 s, no viewpoint rule, N 10)"


def _mrclam_cells(rows, defaults):
    """MRCLAM's cells of one setting: mean `da_accuracy_real`, its paired difference from the defaults' runs
    (`defaults`; None for the defaults' own row), mean ATE, mean `clutter_rejected`."""
    names = sorted(rows)
    accuracy = [rows[name]["da_accuracy_real"] for name in names]
    if defaults is None:
        difference = "–"
    else:
        s = summary([rows[name]["da_accuracy_real"] - defaults[name]["da_accuracy_real"] for name in names])
        difference = (f"{s['mean']:+.3f} [{s['ci_low']:+.3f}, {s['ci_high']:+.3f}], {s['higher']} / "
                      f"{s['lower']}")
    return [mean_cell(accuracy), difference, mean_cell([rows[name]["ate_rmse"] for name in names]),
            mean_cell([rows[name]["clutter_rejected"] for name in names], 2)]


def defaults_table(settings, results):
    """The section's table: a row per setting (settings[0] the defaults), from results {(setting index, family):
    {log name: metrics}}, with ("known", "KITTI") holding known association's runs of the KITTI logs."""
    families = {family for s, family in results if s == 0}
    lines = []
    header = []
    if "MRCLAM" in families:
        header += [f"MRCLAM ({len(results[(0, 'MRCLAM')])} runs): mean `da_accuracy_real`",
                   "paired difference [95 % bootstrap], runs higher / lower", "mean ATE [m]", "mean `clutter_rejected`"]
    if "Lost in the Woods" in families:
        header.append("Lost in the Woods")
    if "KITTI" in families:
        header.append(f"KITTI 00 / 07 ({len(results[(0, 'KITTI')])} logs): ATE ≤ 2 × known's, mean ATE [m]")
    for family in ("KITTI tracking 1 Hz", "KITTI tracking 10 Hz"):
        if family in families:
            header.append(f"{family.replace('1 Hz', '1 Hz ×5')} ({len(results[(0, family)])} seq.)")
    lines += ["`mm-nh`, one setting changed at a time from the defaults. MRCLAM: robots 1-5 × label seeds "
              f"{LABEL_SEEDS[0]}-{LABEL_SEEDS[-1]}, each setting paired with the defaults' runs of the same logs. "
              "Lost in the Woods: `da_accuracy_real` / ATE [m]. KITTI 00 and 07 seeds 1-8: on how many logs mm-nh's "
              "ATE is within 2 × known association's (the first half of the issue's target; ≤ ml's, the other half, "
              "is in the association section) and the mean ATE. KITTI tracking: mean `da_accuracy_real` / mean "
              "`clutter_rejected_moving` / mean `clutter_rejected_false_positive` over the sequences (a count in "
              "brackets where a metric is undefined on some: 0006 has no static landmark).",
              "", "| setting | " + " | ".join(header) + " |", "|---|" + "---|" * len(header)]
    for s, setting in enumerate(settings):
        cells = []
        if "MRCLAM" in families:
            cells += _mrclam_cells(results[(s, "MRCLAM")], results[(0, "MRCLAM")] if s else None)
        if "Lost in the Woods" in families:
            m = results[(s, "Lost in the Woods")]["litw"]
            cells.append(f"{cell(m['da_accuracy_real'])} / {cell(m['ate_rmse'])}")
        if "KITTI" in families:
            runs, known = results[(s, "KITTI")], results[("known", "KITTI")]
            within = sum(runs[name]["ate_rmse"] <= 2 * known[name]["ate_rmse"] for name in runs)
            cells.append(f"{within} of {len(runs)}, {mean_cell([m['ate_rmse'] for m in runs.values()])}")
        for family in ("KITTI tracking 1 Hz", "KITTI tracking 10 Hz"):
            if family in families:
                runs = list(results[(s, family)].values())
                cells.append(" / ".join(mean_cell([m.get(key) for m in runs]) for key in
                                        ("da_accuracy_real", "clutter_rejected_moving",
                                         "clutter_rejected_false_positive")))
        lines.append(f"| {_label(setting)} | " + " | ".join(cells) + " |")
    return lines


def association_defaults_section(semslam, data, scratch):
    lines = ["## The unassigned rule's defaults: μ, M, Δt, the viewpoint rule and N swept on more than one log "
             "(issues 10, 11)", ""]
    logs = _logs(semslam, data, scratch)
    if not logs:
        return lines + ["None of MRCLAM, Lost in the Woods, the KITTI odometry poses or KITTI tracking is present: "
                        "section skipped.", ""]
    settings = _settings()
    jobs = []  # (setting index or "known", family, name, run folder, command)
    for s, setting in enumerate(settings):
        flags = setting_flags(setting)
        for family, name, log in logs:
            out = os.path.join(scratch, f"defaults_{s}_{name}")
            jobs.append((s, family, name, out, [semslam, "run", "--overwrite", "--quiet", "--method", "mm-nh", "--in",
                                                log, "--out", out, "--no-covariances"] + flags))
    for family, name, log in logs:
        if family == "KITTI":
            out = os.path.join(scratch, f"defaults_known_{name}")
            jobs.append(("known", family, name, out, [semslam, "run", "--overwrite", "--quiet", "--method", "known",
                                                      "--in", log, "--out", out, "--no-covariances"]))
    # the longest runs first, so that both workers stay busy to the end
    order = sorted(jobs, key=lambda job: (job[1] not in ("KITTI", "MRCLAM"), job[1] != "KITTI"))
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, (os.cpu_count() or 2))) as pool:
        list(pool.map(lambda job: run_checked(job[4]), order))
    results = {}
    for s, family, name, out, _ in jobs:
        results.setdefault((s, family), {})[name] = read_metrics(out)
    lines += defaults_table(settings, results)
    lines += ["", "```sh",
              "build/bin/semslam convert mrclam ../shared/data/mrclam/MRCLAM_Dataset6 --robot R --classes 3 "
              "--misclassification 0.1 --keyframe-period 1 --seed S --out LOG   # R 1-5, S 1-8",
              "build/bin/semslam run --method mm-nh --in LOG --out DIR --no-covariances "
              "[--unassigned-rate MU] [--unassigned-rate-weight W] [--confirmations M] "
              "[--confirmation-spacing SECONDS] [--confirmation-viewpoint-sigmas K] [--patience N]",
              "```",
              "The other logs: the Lost in the Woods conversion of the association section and docs/datasets.md "
              "(3 classes, 10 %, 1 s keyframes), the KITTI 00 and 07 simulations of the association section (seeds "
              "1-8), and the KITTI tracking conversions `semslam convert kitti-tracking ../shared/data/kitti-tracking "
              "--sequence N --keyframe-period 1 --odometry noisy --odom-noise-scale 5 --seed 1` (1 Hz) and `... "
              "--sequence N --odometry orbslam` (10 Hz).", ""]
    return lines
