"""docs/results.md section of issue 11's study: real detector output through paper B's five methods; used by
make_results.py (section `kitti-tracking`) and, on a small seeded cut, by tests/scripts/test_results_kitti_tracking.py.

Data: ../shared/data/kitti-tracking, KITTI tracking sequences 0000-0010 (PointRCNN detections, labels with track
ids, ORB-SLAM3 stereo poses; docs/datasets.md, "KITTI tracking"). For every sequence and every configuration

    semslam convert kitti-tracking DIR --sequence N [--keyframe-period 1]
        (--odometry orbslam | --odometry noisy --odom-noise-scale K --seed 1)
    semslam run --method M --in LOG --out RUN --no-covariances        M in known ml gpda mm mm-nh
    semslam eval rpe --est RUN/trajectory.tum --ref RUN/truth.tum --delta 10 --delta-unit m --pairs-from-reference
                                                                        (noisy odometry only)

One noise seed serves every scale and both keyframe rates, so the draws are paired: the converter draws the noise
per 10 Hz frame from std::mt19937(seed) in frame order, δ_K = K δ_1, and keyframing composes the same draws.
ATE (metrics.json's `ate_rmse`, SE(3)-aligned) and RPE are recovery of the reference trajectory, reported for noisy
odometry only: with `orbslam` the odometry is made of the reference, so dead reckoning scores 0.

Every number comes from a run's metrics.json (docs/metrics.md) or from `semslam eval rpe --json`; nothing is
computed here but means over sequences (of the sequences where a metric is defined: sequence 0006 has no static
landmark, so no real detection), except the read-out's ceiling of the confirmation rule, which
python/confirmation_ceiling.py reads from the logs themselves. Subprocesses run two at a time (the machine's two cores).
"""
import concurrent.futures
import csv
import json
import math
import os
import subprocess
import sys
import time
from typing import NamedTuple, Optional

import confirmation_ceiling
from results_commands import cell, run_checked

HERE = os.path.dirname(os.path.abspath(__file__))
METHODS = ["known", "ml", "gpda", "mm", "mm-nh"]
SEQUENCES = list(range(11))
# Possibly outside PointRCNN's training split (the issue); reported apart from the others.
OUTSIDE_TRAINING = [1, 6, 8, 10]
SEED = 1
WORKERS = 2
RPE_DELTA_METRES = 10


class Config(NamedTuple):
    """One conversion: keyframe period (s; None: every 10 Hz frame) and noise scale (None: `orbslam`)."""
    period: Optional[float]
    scale: Optional[float]

    @property
    def rate(self):
        return "10 Hz" if self.period is None else f"{1.0 / self.period:g} Hz"

    @property
    def odometry(self):
        return "orbslam" if self.scale is None else f"noisy ×{self.scale:g}"

    @property
    def noisy(self):
        return self.scale is not None

    @property
    def name(self):
        return ("10hz" if self.period is None else f"{1.0 / self.period:g}hz") + (
            "-orbslam" if self.scale is None else f"-noise{self.scale:g}")

    def convert_arguments(self, seed=SEED):
        arguments = [] if self.period is None else ["--keyframe-period", f"{self.period:g}"]
        if self.scale is None:
            return arguments + ["--odometry", "orbslam"]
        return arguments + ["--odometry", "noisy", "--odom-noise-scale", f"{self.scale:g}", "--seed", str(seed)]


ONE_HZ = [Config(1.0, None), Config(1.0, 1.0), Config(1.0, 5.0), Config(1.0, 10.0)]
TEN_HZ = [Config(None, None), Config(None, 1.0), Config(None, 5.0), Config(None, 10.0)]
# Every rate with every odometry, as the issue asks: measured on this 2-core machine, a 10 Hz run of a long sequence
# (0007, 0009: 800 frames, ~3,000 detections) takes ~40 s per DA-unknown method, and the 10 Hz runs are nearly all
# of the section's time (12.5 min with two 10 Hz configurations, 2026-12-02; the section prints its own).
CONFIGS = ONE_HZ + TEN_HZ
READOUT = Config(1.0, 5.0)  # the "What must hold" configuration

# (metrics.json key, column title): association first, then the trajectory (noisy odometry only).
ASSOCIATION_COLUMNS = [("da_accuracy_real", "da_accuracy_real"), ("pairwise_precision", "pairwise precision"),
                       ("pairwise_recall", "pairwise recall"), ("clutter_rejected_moving", "clutter rej. moving"),
                       ("clutter_rejected_false_positive", "clutter rej. false pos."),
                       ("landmarks_merged", "merged"), ("landmarks_split", "split")]
TRAJECTORY_COLUMNS = [("ate_rmse", "ATE [m]"), ("rpe_rmse", f"RPE {RPE_DELTA_METRES} m [m]")]


def sequence_name(sequence):
    return f"{sequence:04d}"


def convert_command(semslam, folder, sequence, config, out, max_steps=None, seed=SEED):
    command = [semslam, "convert", "kitti-tracking", folder, "--sequence", str(sequence), "--out", out]
    command += config.convert_arguments(seed)
    return command + (["--max-steps", str(max_steps)] if max_steps else [])


def run_command(semslam, method, log, out, extra=()):
    return [semslam, "run", "--overwrite", "--method", method, "--in", log, "--out", out, "--no-covariances", *extra]


def rpe_command(semslam, run_dir):
    return [semslam, "eval", "rpe", "--est", os.path.join(run_dir, "trajectory.tum"), "--ref",
            os.path.join(run_dir, "truth.tum"), "--format", "tum", "--delta", str(RPE_DELTA_METRES), "--delta-unit",
            "m", "--pairs-from-reference", "--json"]


def _rpe(semslam, run_dir):
    """`semslam eval rpe --json` of a run, or {} when it has no pair of poses 10 m apart (a short cut)."""
    result = subprocess.run(rpe_command(semslam, run_dir), capture_output=True, text=True)
    if result.returncode == 0:
        return json.loads(result.stdout)
    if "pair" in result.stderr:
        return {}
    sys.exit(f"results_kitti_tracking.py: {' '.join(rpe_command(semslam, run_dir))} failed:\n{result.stderr}")


def log_counts(log):
    """Steps and detections of a converted log by truth: real (a landmark id), moving (not-a-landmark with a
    clutter_source), false positive (not-a-landmark without), unknown; and the landmarks named."""
    counts = {"steps": 0, "real": 0, "moving": 0, "false_positive": 0, "unknown": 0}
    landmarks = set()
    with open(log) as f:
        next(f)  # the header
        for line in f:
            record = json.loads(line)
            counts["steps"] += 1
            for detection in record["detections"]:
                truth = detection.get("truth")
                if truth == "not-a-landmark":
                    counts["moving" if "clutter_source" in detection else "false_positive"] += 1
                elif truth == "unknown":
                    counts["unknown"] += 1
                elif truth is not None:
                    counts["real"] += 1
                    landmarks.add(truth)
    counts["landmarks"] = len(landmarks)
    return counts


def run_study(semslam, folder, scratch, sequences=SEQUENCES, configs=CONFIGS, methods=METHODS, max_steps=None,
              seed=SEED, workers=WORKERS, run_arguments=()):
    """Converts, runs and scores every (sequence, configuration, method); returns (rows, logs): one row per run,
    a dict of the metrics the tables show plus sequence, config, method, run (its folder) and time_s; logs maps
    (sequence, config) to (log path, log_counts). `run_arguments` go to every `semslam run`."""
    os.makedirs(scratch, exist_ok=True)
    logs = {}
    for sequence in sequences:
        for config in configs:
            path = os.path.join(scratch, f"kitti-{sequence_name(sequence)}-{config.name}.jsonl")
            logs[(sequence, config)] = path
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        list(pool.map(lambda item: run_checked(convert_command(semslam, folder, item[0][0], item[0][1], item[1], max_steps,
                                                        seed)), logs.items()))
        jobs = []
        for (sequence, config), log in logs.items():
            for method in methods:
                out = os.path.join(scratch, f"kitti-{sequence_name(sequence)}-{config.name}", method)
                jobs.append((sequence, config, method, log, out))
        list(pool.map(lambda job: run_checked(run_command(semslam, job[2], job[3], job[4], run_arguments)), jobs))
        noisy = [job for job in jobs if job[1].noisy]
        rpe = dict(zip([job[4] for job in noisy], pool.map(lambda job: _rpe(semslam, job[4]), noisy)))
    rows = []
    for sequence, config, method, log, out in jobs:
        with open(os.path.join(out, "metrics.json")) as f:
            metrics = json.load(f)
        row = {"sequence": sequence, "config": config, "method": method, "run": out, "log": log,
               "time_s": metrics.get("time_s"), "landmarks_estimated": metrics.get("landmarks_estimated"),
               "landmarks_true": metrics.get("landmarks_true")}
        for key, _ in ASSOCIATION_COLUMNS:
            row[key] = metrics.get(key)
        row["ate_rmse"] = metrics.get("ate_rmse") if config.noisy else None
        row["rpe_rmse"] = rpe[out].get("rmse") if config.noisy else None
        rows.append(row)
    return rows, {key: (path, log_counts(path)) for key, path in logs.items()}


def table_header():
    titles = ["keyframes", "odometry", "method"] + [t for _, t in ASSOCIATION_COLUMNS] + [
        "landmarks (true)"] + [t for _, t in TRAJECTORY_COLUMNS] + ["time [s]"]
    return ["| " + " | ".join(titles) + " |", "|" + "---|" * len(titles)]


def table_row(row):
    cells = [row["config"].rate, row["config"].odometry, row["method"]]
    cells += [cell(row[key]) for key, _ in ASSOCIATION_COLUMNS]
    cells.append(f"{cell(row['landmarks_estimated'])} ({cell(row['landmarks_true'])})")
    cells += [cell(row[key]) for key, _ in TRAJECTORY_COLUMNS]
    cells.append(cell(row["time_s"], 2))
    return "| " + " | ".join(cells) + " |"


def mean(values):
    """The mean of the defined values and how many there were (None when none is)."""
    defined = [v for v in values if v is not None and not (isinstance(v, float) and math.isnan(v))]
    return (sum(defined) / len(defined) if defined else None), len(defined)


def summary_table(rows, sequences, configs, methods):
    """Means over `sequences` per configuration and method."""
    keys = [key for key, _ in ASSOCIATION_COLUMNS] + [key for key, _ in TRAJECTORY_COLUMNS]
    titles = ["keyframes", "odometry", "method"] + [t for _, t in ASSOCIATION_COLUMNS + TRAJECTORY_COLUMNS] + [
        "time [s]"]
    lines = ["| " + " | ".join(titles) + " |", "|" + "---|" * len(titles)]
    for config in configs:
        for method in methods:
            selected = [r for r in rows
                        if r["config"] == config and r["method"] == method and r["sequence"] in sequences]
            if not selected:
                continue
            cells = [config.rate, config.odometry, method]
            for key in keys:
                value, n = mean([r[key] for r in selected])
                cells.append(cell(value) + ("" if n in (0, len(selected)) else f" ({n})"))
            cells.append(cell(mean([r["time_s"] for r in selected])[0], 2))
            lines.append("| " + " | ".join(cells) + " |")
    return lines


def readout(rows, sequences):
    """The issue's "What must hold" at READOUT: mm-nh's mean da_accuracy_real and clutter_rejected_moving over the
    sequences (≥ 0.9 and ≥ 0.8), and on how many sequences mm-nh is no worse than ml on both (≥ 9 of 11). A metric
    undefined for both methods (no real detection, no moving clutter) counts as no worse."""
    at = {(r["sequence"], r["method"]): r for r in rows if r["config"] == READOUT}
    result = {"da_accuracy_real": mean([at[(s, "mm-nh")]["da_accuracy_real"] for s in sequences if (s, "mm-nh") in at]),
              "clutter_rejected_moving": mean([at[(s, "mm-nh")]["clutter_rejected_moving"] for s in sequences
                                               if (s, "mm-nh") in at]),
              "worse": [], "compared": 0}
    for s in sequences:
        if (s, "mm-nh") not in at or (s, "ml") not in at:
            continue
        result["compared"] += 1
        worse = []
        for key in ("da_accuracy_real", "clutter_rejected_moving"):
            mm, ml = at[(s, "mm-nh")][key], at[(s, "ml")][key]
            if mm is not None and ml is not None and mm < ml:
                worse.append(f"{key} {mm:.3f} < {ml:.3f}")
            elif mm is None and ml is not None:
                worse.append(f"{key} undefined for mm-nh")
        if worse:
            result["worse"].append((s, worse, null_disagreements(at[(s, "ml")]["run"], at[(s, "mm-nh")]["run"])))
    return result


def _final_verdicts(run):
    """(step, detection) → (on a landmark, truth, chi2 or None) from a run's associations.csv (io/RunFolder.h)."""
    path = os.path.join(run, "associations.csv")
    with open(path, newline="") as f:
        return {(int(r["step"]), int(r["detection"])): (r["landmark"] != "null", r["truth"],
                                                        float(r["chi2"]) if r["chi2"] else None)
                for r in csv.DictReader(f)}


def null_disagreements(ml_run, mm_run):
    """Where two runs of one log differ on whether a detection ends on a landmark at all (`null` in
    associations.csv: the null hypothesis, a dropped provisional landmark, or rejected), which decides most of
    `da_accuracy_real` and the clutter figures here (docs/metrics.md counts a real detection on null as wrong):
      real_on_null_mm: ml's chi2 of each real detection (truth a landmark) that mm-nh leaves on null and ml keeps;
      real_on_null_ml: how many real detections ml leaves on null and mm-nh keeps;
      clutter_kept_mm, clutter_kept_ml: how many clutter detections one method keeps on a landmark, the other not.
    Which landmark a kept detection is on (an identity decision) is left to the metrics."""
    ml, mm = _final_verdicts(ml_run), _final_verdicts(mm_run)
    if ml.keys() != mm.keys():
        raise ValueError(f"{ml_run} and {mm_run}: the runs are not of one log (their detections differ)")
    result = {"real_on_null_mm": [], "real_on_null_ml": 0, "clutter_kept_mm": 0, "clutter_kept_ml": 0}
    for key, (ml_kept, truth, ml_chi2) in sorted(ml.items()):
        mm_kept = mm[key][0]
        if truth == "unknown" or ml_kept == mm_kept:
            continue
        if truth == "not-a-landmark":
            result["clutter_kept_mm" if mm_kept else "clutter_kept_ml"] += 1
        elif ml_kept:
            result["real_on_null_mm"].append(ml_chi2)
        else:
            result["real_on_null_ml"] += 1
    return result


def describe_disagreements(d):
    """One clause for docs/results.md from null_disagreements' result."""
    parts = []
    if d["real_on_null_mm"]:
        chi2 = sorted(d["real_on_null_mm"])
        parts.append(f"{len(chi2)} real detection{'s' if len(chi2) > 1 else ''} on null for mm-nh that ml keeps "
                     f"(ml's χ² there {chi2[0]:.2f}" + (f"-{chi2[-1]:.2f})" if len(chi2) > 1 else ")"))
    if d["real_on_null_ml"]:
        parts.append(f"{d['real_on_null_ml']} the other way round")
    if d["clutter_kept_mm"] or d["clutter_kept_ml"]:
        parts.append(f"clutter kept on a landmark by mm-nh only {d['clutter_kept_mm']}, by ml only "
                     f"{d['clutter_kept_ml']}")
    return "; ".join(parts) if parts else "no detection on a landmark for one and on null for the other"


CONFIRMATION_VARIANT = ["--confirmations", "1"]
# mm-nh's null escape widened to a single null detection of a landmark seen off null at most 1 s before it
# (docs/association-front-end.md §6c; opt-in): run at the read-out configuration and at 10 Hz with noise ×5.
WINDOW_VARIANT = ["--null-escape-window", "1"]
WINDOW_CONFIGS = [READOUT, Config(None, 5.0)]


def window_lines(rows, window_rows):
    """The read-out with mm-nh's runs taken from WINDOW_VARIANT (ml's from the default runs), and per configuration
    of WINDOW_CONFIGS mm-nh's means without and with the window."""
    r = readout([row for row in rows if row["method"] != "mm-nh"] + window_rows, SEQUENCES)
    da, moving = r["da_accuracy_real"][0], r["clutter_rejected_moving"][0]
    lines = [f"With `semslam run --method mm-nh ... {' '.join(WINDOW_VARIANT)}` (opt-in; mm-nh's null escape also "
             "tries a landmark's single detection on null when the landmark was seen off null at most 1 s before "
             "it, docs/association-front-end.md §6c), the read-out is: mean `da_accuracy_real` "
             f"{cell(da)}, moving clutter rejected {cell(moving)}, no worse than ml on both on "
             f"{r['compared'] - len(r['worse'])} of {r['compared']} sequences"
             + (" (" + "; ".join(f"{sequence_name(s)}: " + ", ".join(w) for s, w, _ in r["worse"]) + ")"
                if r["worse"] else "") + ". Means over the sequences, default against the window:", "",
             "| configuration | null escape window | da_accuracy_real | clutter rej. moving | clutter rej. false pos. "
             "| ATE [m] | time [s] (sum) |", "|---|---|---|---|---|---|---|"]
    for config in WINDOW_CONFIGS:
        for label, source in (("off (default)", rows), ("1 s", window_rows)):
            selected = [row for row in source if row["config"] == config and row["method"] == "mm-nh"]
            if not selected:
                continue
            cells = [cell(mean([row[key] for row in selected])[0]) for key in
                     ("da_accuracy_real", "clutter_rejected_moving", "clutter_rejected_false_positive", "ate_rmse")]
            total = sum(row["time_s"] for row in selected if row["time_s"] is not None)
            lines.append(f"| {config.rate}, {config.odometry} | {label} | " + " | ".join(cells) + f" | {total:.1f} |")
    return lines + [""]


def ceiling_lines(logs, sequences, spacing=confirmation_ceiling.DEFAULT_SPACING):
    """What the read-out's logs allow the confirmation rule (M = 2 detections Δt apart) to reach, from the logs
    alone (python/confirmation_ceiling.py): its ceiling on `da_accuracy_real`, and the real and clutter detections
    that are seen once and never in view again, which no rule deciding from time and geometry can tell apart."""
    counts = {s: confirmation_ceiling.ceiling(logs[(s, READOUT)][0], spacing) for s in sequences
              if (s, READOUT) in logs}
    if not counts:
        return []
    total = {key: sum(c[key] for c in counts.values()) for key in next(iter(counts.values())) if key != "ceiling"}
    ceiling, n = mean([c["ceiling"] for c in counts.values()])
    keep_real, _ = mean([(c["real_confirmable"] + c["real_never_in_view_again"]) / c["real"]
                         for c in counts.values() if c["real"]])
    keep_moving, moving_n = mean([1 - c["moving_never_in_view_again"] / c["moving"]
                                  for c in counts.values() if c["moving"]])
    unconfirmable = total["real"] - total["real_confirmable"]
    return [f"**What the 1 Hz logs allow** (`python3 python/confirmation_ceiling.py LOG ...` on the read-out's logs; "
            "no run): a provisional landmark is confirmed by a second detection at least "
            f"{spacing:g} s after its first. {unconfirmable} of the {total['real']} real detections belong to cars "
            f"whose detections all fall within less than {spacing:g} s (seen on one keyframe), so under the rule they "
            "end on a dropped landmark whatever the method: the rule's ceiling on `da_accuracy_real` is "
            f"{cell(ceiling)} (mean over the {n} sequences of the confirmable fraction; up to the metric's identity "
            "matching, which may credit a detection on a landmark confirmed by another car's detections). Of those "
            f"{unconfirmable}, {total['real_never_in_view_again']} never come into the sensor's field again "
            "(through the reference poses), so no missed detection can refute them either; neither can it refute "
            f"{total['moving_never_in_view_again']} of the {total['moving']} moving-clutter and "
            f"{total['false_positive_never_in_view_again']} of the {total['false_positive']} false-positive "
            "detections. On these sightings time and geometry give odds of about "
            f"{total['real_never_in_view_again']} real to "
            f"{total['moving_never_in_view_again'] + total['false_positive_never_in_view_again']} clutter, so "
            "dropping them, as the rule does, is the decision that errs least, and nothing else in the log tells "
            "them apart. A rule that kept every one would reach at most "
            f"{cell(keep_real)} on `da_accuracy_real` and at most {cell(keep_moving)} on moving clutter (means over "
            f"{moving_n} sequences; that only if it rejected every other moving detection, where mm-nh now keeps "
            "some); one that kept some of them, having nothing to choose them by, would keep moving clutter in "
            f"about the proportion {total['moving_never_in_view_again']} : {total['real_never_in_view_again']} to "
            "the real sightings it gains (docs/association-front-end.md §5e).", ""]


def variant_table(rows, variant):
    """Per method, the READOUT means of the default runs against those of CONFIRMATION_VARIANT."""
    keys = ["da_accuracy_real", "clutter_rejected_moving", "clutter_rejected_false_positive", "landmarks_estimated"]
    lines = ["| method | confirmations | da_accuracy_real | clutter rej. moving | clutter rej. false pos. | "
             "landmarks (true) |", "|---|---|---|---|---|---|"]
    for method in METHODS:
        for label, source in (("2 (default)", rows), ("1", variant)):
            selected = [r for r in source if r["config"] == READOUT and r["method"] == method]
            if not selected:
                continue
            cells = []
            for key in keys:
                value, n = mean([r[key] for r in selected])
                cells.append(cell(value, 1 if key == "landmarks_estimated" else 3) +
                             ("" if n in (0, len(selected)) else f" ({n})"))
            true_landmarks = cell(mean([r["landmarks_true"] for r in selected])[0], 1)
            lines.append(f"| {method} | {label} | " + " | ".join(cells[:3]) + f" | {cells[3]} ({true_landmarks}) |")
    return lines


def _shown_convert(shown, semslam, folder, config, sequence="N"):
    command = convert_command(semslam, folder, 0, config, "LOG.jsonl")
    command[command.index("--sequence") + 1] = str(sequence)
    return shown(command)


def _figure(semslam_python, rows, logs, sequence, figure, title):
    row = next(r for r in rows if r["sequence"] == sequence and r["config"] == READOUT and r["method"] == "mm-nh")
    run_checked([semslam_python, os.path.join(HERE, "plot_kitti_tracking.py"), logs[(sequence, READOUT)][0], row["run"],
          "--out", figure, "--title", title])


# The sequence drawn for each kind: the one with the most static landmarks of its group.
FIGURE_SEQUENCES = {"inside": 9, "outside": 1}

# What real detector output changes, per method. The numbers are the runs' means (filled in at every regeneration);
# the mechanisms were traced with python/diagnose_association.py on the runs of 2026-12-02 (READOUT_TRACE) and are
# stated as such: after a change of the association front end they are the first thing to re-check.
def _method_paragraph(rows):
    def m(method, key, config=READOUT, digits=3):
        return cell(mean([r[key] for r in rows if r["method"] == method and r["config"] == config])[0], digits)

    ten = Config(None, 5.0)
    ten_orb = Config(None, None)
    return [
        "**What real detector output changes, per method** (means over the eleven sequences, from the tables "
        "below; the mechanisms as traced on 2026-12-02):", "",
        "- `known` reads the truth as its association, so it is the ceiling on every association figure, but not on "
        "ATE: ATE is the distance to the ORB-SLAM3 reference, which the detections themselves disagree with by "
        "decimetres to a metre (with `orbslam` odometry, known and ml on 0009 at 1 Hz end 0.85 and 0.99 m RMSE from "
        "the trajectory they were given as odometry), so the more detections a method uses the further it may move "
        "from the reference "
        f"(1 Hz ×5: known {m('known', 'ate_rmse')} m, mm-nh {m('mm-nh', 'ate_rmse')}, ml {m('ml', 'ate_rmse')}; "
        f"10 Hz ×5: {m('known', 'ate_rmse', ten)}, {m('mm-nh', 'ate_rmse', ten)} and {m('ml', 'ate_rmse', ten)} m).",
        "- For `ml`, `gpda`, `mm` and `mm-nh` alike, the association front end (the unassigned birth rule and its "
        "provisional landmarks, docs/association-front-end.md) decides more than the method does. A provisional "
        "landmark is confirmed by a second detection at least 1 s after the first: at 1 Hz many parked cars are in "
        "view for only 2-3 s, and a car seen on two consecutive keyframes is confirmed "
        f"(`da_accuracy_real` {m('ml', 'da_accuracy_real')} for ml and {m('mm-nh', 'da_accuracy_real')} for mm-nh at "
        "1 Hz ×5). The same rule rejects most moving clutter for every method, mm-nh's null hypothesis or not "
        f"(moving clutter rejected: ml {m('ml', 'clutter_rejected_moving')}, mm-nh "
        f"{m('mm-nh', 'clutter_rejected_moving')}): a moving object has to stay within one landmark's gate for a "
        "second to be confirmed. At 10 Hz every method confirms nearly "
        f"every static car (`da_accuracy_real` {m('ml', 'da_accuracy_real', ten_orb)} for ml and "
        f"{m('mm-nh', 'da_accuracy_real', ten_orb)} for mm-nh with ORB-SLAM3 odometry), and clutter that comes "
        "back over a second is confirmed too: a false positive the detector repeats on the same structure "
        "is as static as a parked car (clutter-only landmarks of 3-5 detections with χ² per detection 0.4-8 in "
        f"0009, traced 2026-12-02), so false positives are rejected at "
        f"{m('ml', 'clutter_rejected_false_positive', ten_orb)} (ml) and "
        f"{m('mm-nh', 'clutter_rejected_false_positive', ten_orb)} (mm-nh), moving objects at "
        f"{m('ml', 'clutter_rejected_moving', ten_orb)} and {m('mm-nh', 'clutter_rejected_moving', ten_orb)}. "
        "So the 10 Hz maps hold several times more landmarks than there are static tracks (on average "
        f"{m('ml', 'landmarks_estimated', ten_orb, 1)} for ml and {m('mm-nh', 'landmarks_estimated', ten_orb, 1)} "
        f"for mm-nh against {m('known', 'landmarks_estimated', ten_orb, 1)}): confirmed clutter, and objects of `unknown` "
        "truth (vans, slowly moving cars, boxes in DontCare regions), which every method maps and no metric scores.",
        "- `ml`, `gpda` and `mm` give the same figures to the last digit on most logs here and differ only where the "
        "noise is large (1 Hz ×10); presumably (not traced) because static cars stand metres apart, well beyond the "
        "detector's σ (0.1-0.4 m), so there is rarely a second candidate for EM or the mixture to weigh.",
        "- `mm-nh` is the one method whose null hypothesis can reject a detection near a landmark. With noisy "
        "odometry that keeps it closer to the reference (ATE above) and helps the clutter figures at 10 Hz (moving "
        f"{m('mm-nh', 'clutter_rejected_moving', ten)} against ml's {m('ml', 'clutter_rejected_moving', ten)} at "
        "×5); at 1 Hz, once the noise puts a car's second detection outside its landmark's component, the "
        "detection goes to the null hypothesis and nothing pulls the pose back (trace 2 above) until the escape "
        "of §6b puts the car's null detections back together: `da_accuracy_real` "
        f"{m('mm-nh', 'da_accuracy_real')} against ml's {m('ml', 'da_accuracy_real')} at 1 Hz ×5.", ""]


def kitti_tracking_section(semslam, data, scratch, shown, python=None):
    python = python or sys.executable
    folder = os.path.join(data, "kitti-tracking")
    lines = ["## Real detector output: KITTI tracking 0000-0010 (issue 11)", ""]
    if not os.path.isdir(folder):
        return lines + [f"The KITTI tracking data is not at {folder}: section skipped.", ""]
    started = time.monotonic()
    rows, logs = run_study(semslam, folder, os.path.join(scratch, "kitti-tracking"))
    variant, _ = run_study(semslam, folder, os.path.join(scratch, "confirmations-1"), configs=[READOUT],
                           run_arguments=CONFIRMATION_VARIANT)
    window, _ = run_study(semslam, folder, os.path.join(scratch, "null-escape-window-1"), configs=WINDOW_CONFIGS,
                          methods=["mm-nh"], run_arguments=WINDOW_VARIANT)
    inside = [s for s in SEQUENCES if s not in OUTSIDE_TRAINING]
    configs = [c for c in CONFIGS]
    lines += [
        "PointRCNN detections (cars, pedestrians, cyclists) with the KITTI tracking labels as truth "
        "(docs/datasets.md, \"KITTI tracking\"): a static track is a landmark, a track that moves more than 5 m is "
        "*moving* clutter (its `clutter_source`), an unmatched detection a *false positive*, anything in between "
        "`unknown` and left out of every metric (docs/metrics.md). Keyframes at 1 Hz and at the native 10 Hz; "
        "odometry ORB-SLAM3's (`orbslam`) or that plus seeded noise at scales 1, 5 and 10 (`noisy ×K`, seed "
        f"{SEED}, paired across scales and rates). The five methods at their defaults, incremental smoother, "
        "`--no-covariances`. ATE (SE(3)-aligned RMSE) and RPE (translation RMSE over "
        f"{RPE_DELTA_METRES} m pairs of the reference) measure recovery of the ORB-SLAM3 reference and are shown "
        "for noisy odometry only. Sequences 0001, 0006, 0008 and 0010 may lie outside the detector's training split "
        "and are reported apart. Sequence 0006 has no static landmark (every matched car moves), so it has no "
        "`da_accuracy_real` or pairwise figure; means are over the sequences where a metric is defined (the count "
        "in brackets where that is not all of them).", "",
        f"The whole section (convert {len(logs) + len(SEQUENCES) + len(WINDOW_CONFIGS) * len(SEQUENCES)} logs, "
        f"{len(rows) + len(variant) + len(window)} runs, RPE of "
        f"the noisy ones, 2 subprocesses at a time, then the figures) took **{{minutes}} min** on this machine "
        f"({os.cpu_count()} cores, shared with other builds while it ran); nearly all of it is the 10 Hz runs: a "
        "run of the long sequences (0007, 0009: 800 frames, ~3,000 detections) takes ~40 s per DA-unknown method.",
        ""]

    # The read-out first.
    r = readout(rows, SEQUENCES)
    da, da_n = r["da_accuracy_real"]
    moving, moving_n = r["clutter_rejected_moving"]
    no_worse = r["compared"] - len(r["worse"])
    lines += ["### The issue's read-out: 1 Hz keyframes, noise ×5, sequences 0000-0010", "",
              "| requirement | measured | met |", "|---|---|---|",
              f"| mm-nh mean `da_accuracy_real` ≥ 0.9 | {cell(da)} (over {da_n} sequences) | "
              f"{'yes' if da is not None and da >= 0.9 else 'no'} |",
              f"| mm-nh mean `clutter_rejected_moving` ≥ 0.8 | {cell(moving)} (over {moving_n} sequences) | "
              f"{'yes' if moving is not None and moving >= 0.8 else 'no'} |",
              f"| mm-nh no worse than ml on both, on ≥ 9 of 11 sequences | {no_worse} of {r['compared']} | "
              f"{'yes' if no_worse >= 9 else 'no'} |", ""]
    if r["worse"]:
        lines += ["Where mm-nh is worse than ml, and the detections on which the two runs disagree about being on a "
                  "landmark at all (null: the null hypothesis, a dropped provisional landmark, or rejected; χ² of a "
                  "3D detection at ml's final estimate, 3 on average for one that fits):", ""]
        lines += [f"- {sequence_name(s)}: " + ", ".join(w) + f"; {describe_disagreements(d)}."
                  for s, w, d in r["worse"]]
        lines += [""]
    lines += window_lines(rows, window)
    lines += ceiling_lines(logs, SEQUENCES)
    lines += ["The same read-out configuration with the provisional landmarks confirmed by their birth detection "
              f"alone (`semslam run ... {' '.join(CONFIRMATION_VARIANT)}`; the default is 2 detections at least 1 s "
              f"apart, docs/association-front-end.md), means over the {len(SEQUENCES)} sequences "
              "(count in brackets where a metric is undefined on some):", ""]
    lines += variant_table(rows, variant) + [""]
    lines += READOUT_TRACE + _method_paragraph(rows)

    # Summaries.
    for title, group in (("inside the detector's training split (0000, 0002-0005, 0007, 0009)", inside),
                         ("possibly outside it (0001, 0006, 0008, 0010)", OUTSIDE_TRAINING)):
        lines += [f"### Summary, sequences {title}", "",
                  f"Means over the {len(group)} sequences per configuration and method.", ""]
        lines += summary_table(rows, group, configs, METHODS) + [""]

    # Figures.
    figures = os.path.join("docs", "figures")
    os.makedirs(figures, exist_ok=True)
    figure_lines = []
    for kind, sequence in FIGURE_SEQUENCES.items():
        figure = os.path.join(figures, f"kitti_tracking_{kind}.png")
        title = (f"KITTI tracking {sequence_name(sequence)} "
                 f"({'inside' if kind == 'inside' else 'possibly outside'} the detector's training split): mm-nh, "
                 f"1 Hz, noise ×5")
        _figure(python, rows, logs, sequence, figure, title)
        figure_lines += [f"![KITTI tracking {sequence_name(sequence)}]({os.path.relpath(figure, 'docs')})", ""]
    lines += ["### Maps", "",
              "mm-nh at 1 Hz, noise ×5, one sequence of each kind: the estimated trajectory and the reference, the "
              "confirmed landmarks (the run's landmarks.csv) against the static tracks, the detections mm-nh left on "
              "no landmark, clutter it put on a landmark, and the moving tracks (detections with a `clutter_source`, "
              "one line per track) through the estimated poses. `python3 python/plot_kitti_tracking.py LOG RUN_DIR "
              "--out FILE.png`.", ""] + figure_lines

    # Per sequence.
    lines += ["### Per sequence", "",
              "Counts per log: steps, detections by truth (real / moving / false positive / unknown) and the static "
              "landmarks they name.", ""]
    for sequence in inside + OUTSIDE_TRAINING:
        kind = "possibly outside the training split" if sequence in OUTSIDE_TRAINING else "inside the training split"
        lines += [f"#### Sequence {sequence_name(sequence)} ({kind})", ""]
        for config in (Config(1.0, None), Config(None, None)):
            if (sequence, config) in logs:
                c = logs[(sequence, config)][1]
                lines.append(f"- {config.rate}: {c['steps']} steps; detections {c['real']} / {c['moving']} / "
                             f"{c['false_positive']} / {c['unknown']}; {c['landmarks']} landmarks.")
        lines += ["", "```sh"]
        for config in configs:
            lines.append(_shown_convert(shown, semslam, folder, config, sequence).replace(
                "LOG.jsonl", f"{sequence_name(sequence)}-{config.name}.jsonl"))
        lines += ["for m in known ml gpda mm mm-nh; do build/bin/semslam run --method $m --in LOG.jsonl "
                  "--out RUN/$m --no-covariances; done",
                  f"build/bin/semslam eval rpe --est RUN/M/trajectory.tum --ref RUN/M/truth.tum --format tum "
                  f"--delta {RPE_DELTA_METRES} --delta-unit m --pairs-from-reference", "```", ""]
        lines += table_header()
        lines += [table_row(r) for r in rows if r["sequence"] == sequence] + [""]
    lines += ["Regenerate this section: `/usr/bin/python3 python/make_results.py --build build --only "
              "kitti-tracking`.", ""]
    minutes = f"{(time.monotonic() - started) / 60:.1f}"
    return [line.replace("{minutes}", minutes) for line in lines]


# Written from python/diagnose_association.py on the read-out's runs of 2026-12-02, reproduced by the commands it
# gives; regenerated numbers above may move, this says what the trace showed then.
READOUT_TRACE = [
    "**Why the read-out is not met: three traces** (reproduce with the commands below).", "",
    "1. *Parked cars seen for 2-3 s (every DA-unknown method; traced 2026-12-02, fixed 2026-12-03).* Under the "
    "former spacing of the confirmation rule, 3 median step periods (3 s at 1 Hz, 0.3 s at 10 Hz), the six static "
    "tracks of sequence 0003 at 1 Hz ×5, in view for 2-3 s each (2-3 keyframe detections), were all dropped "
    "unconfirmed, since a second detection 3 s after the first never came: mm-nh `da_accuracy_real` 0, ml 0.143. "
    "The spacing is now 1 s at every keyframe rate (docs/association-front-end.md §5, measured there at 1 Hz and "
    "10 Hz): a parked car seen on two consecutive 1 Hz keyframes is confirmed, and at 10 Hz a moving car must "
    "stay inside one landmark's gate for a whole second to be confirmed. The `--confirmations 1` table above is "
    "what the rule is worth: without it every DA-unknown method keeps nearly every real detection and rejects no "
    "clutter at all.",
"2. *mm-nh loses a car under noisy odometry (traced 2026-12-02).* Sequence 0009, track 1 (7 keyframe detections): ml puts all 7 on "
    "one estimate (χ² 0.1-1.8 at the final estimate); mm-nh births the landmark at step 0 and puts the other six on "
    "the null hypothesis. Against mm-nh's final landmark and poses, the step-1 detection lies 0.6 m farther and "
    "0.8 m higher than predicted, χ² 63 against the "
    "detection's covariance alone; on `null` it adds no factor, so nothing pulls the pose back and the car's later "
    "detections lie ever further out (χ² 305 at step 6). With `orbslam` odometry the same track is on one estimate "
    "for mm-nh as for ml (0009 at 1 Hz: `da_accuracy_real` 0.682 against 0.687). Since 2026-12-03 mm-nh escapes "
    "this basin (docs/association-front-end.md §6b: a landmark's detections on `null`, two or more, are tried on it "
    "together and kept there where that lowers the objective): all seven detections of the track are on its car. "
    "Where mm-nh is still worse than ml on `da_accuracy_real` in the read-out, this is the mechanism to check "
    "first (`--no-null-escape` shows the run without it).",
"3. *What is left of the gap is the incremental back end (measured 2026-12-04).* Each detection listed above, on "
    "null for mm-nh and on its car for ml, is a re-sighting that a converged solve puts back: with the batch back "
    "end (`semslam run --method mm-nh --smoother batch ...`) mm-nh's `da_accuracy_real` equals ml's on every "
    "sequence (section \"The incremental against the batch back end\"), and `--switch-rounds 5`, which lets the "
    "incremental back end re-choose a mixture at its new estimate, takes it part of the way (mean 0.791; "
    "docs/association-front-end.md §6, where its cost keeps it off by default). Traced on 2026-12-04: each is the "
    "one detection of its car on null, nearly always the car's last, a step after a detection on the car; the "
    "null escape (two or more on null) never tries it. `--null-escape-window 1` (the table above) tries it, and "
    "mm-nh then ends where the batch back end does on the read-out's `da_accuracy_real`.", "",
    "```sh",
    "build/bin/semslam convert kitti-tracking ../shared/data/kitti-tracking --sequence 3 --keyframe-period 1 "
    "--odometry noisy --odom-noise-scale 5 --seed 1 --out 0003.jsonl",
    "build/bin/semslam run --method mm-nh --in 0003.jsonl --out 0003/mm-nh --no-covariances",
    "python3 python/diagnose_association.py 0003/mm-nh",
    "# the same with --sequence 9 (and --odometry orbslam), methods ml and mm-nh; then in 0009/*/associations.csv "
    "the rows whose truth is 1",
    "```", ""]
