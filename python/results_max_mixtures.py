"""docs/results.md sections of paper B's semantic max-mixtures (issue 5); used by make_results.py.

Every run goes through the `semslam` tool; each table row comes from the run's metrics.json, and each section
prints the commands that produced it.
"""
import json
import os
import sys

from results_commands import read_metrics, run_checked

METHODS = ["known", "ml", "gpda", "mm", "mm-nh"]
HERE = os.path.dirname(os.path.abspath(__file__))


def _log_duration(log):
    first = last = None
    with open(log) as f:
        for line in f:
            record = json.loads(line)
            if "time" in record:
                first = record["time"] if first is None else first
                last = record["time"]
    return (last - first) if first is not None else float("nan")


def _number(value, digits=4):
    return "–" if value is None else f"{value:.{digits}f}"


def _error_table(runs, duration):
    lines = ["| method | ATE max [m] | ATE mean | ATE median | ATE RMSE | rot max [rad] | rot mean | rot median | "
             "rot RMSE | DA accuracy | landmarks (true) | NEES mean (95 % band) | time [s] | real-time factor |",
             "|---|" + "---|" * 13]
    for method, folder in runs:
        m = read_metrics(folder)
        nees = (f"{_number(m.get('nees_mean'), 2)} ({_number(m.get('nees_lower'), 2)}–"
                f"{_number(m.get('nees_upper'), 2)})")
        lines.append(
            f"| {method} | {_number(m.get('ate_max'))} | {_number(m.get('ate_mean'))} | {_number(m.get('ate_median'))} | "
            f"{_number(m.get('ate_rmse'))} | {_number(m.get('rot_max'))} | {_number(m.get('rot_mean'))} | "
            f"{_number(m.get('rot_median'))} | {_number(m.get('rot_rmse'))} | {_number(m.get('da_accuracy'))} | "
            f"{m.get('landmarks_estimated')} ({m.get('landmarks_true')}) | {nees} | {_number(m.get('time_s'), 1)} | "
            f"{_number(duration / m['time_s'], 1) if m.get('time_s') else '–'} |")
    return lines


def _methods_on_log(semslam, log, name, scratch, figures, title, extra=()):
    """Runs every method on `log`; returns the table lines, the commands and the trajectory figure."""
    runs = []
    for method in METHODS:
        folder = os.path.join(scratch, name, method)
        run_checked([semslam, "run", "--overwrite", "--method", method, "--in", log, "--out", folder, *extra])
        runs.append((method, folder))
    figure = os.path.join(figures, f"{name}_methods.png")
    run_checked([sys.executable, os.path.join(HERE, "plot_methods.py"), *[f for _, f in runs], "--out", figure,
          "--title", title])
    return _error_table(runs, _log_duration(log)), figure


def max_mixture_sections(semslam, data, scratch, shown):
    figures = os.path.join("docs", "figures")
    os.makedirs(figures, exist_ok=True)
    lines = ["## Semantic max-mixtures and baselines (issue 5, paper B)", "",
             "Every method of paper B on one front end (docs/max-mixtures.md): `known` association, maximum likelihood "
             "(`ml`), EM soft association (`gpda`), max-mixtures (`mm`) and max-mixtures with a null hypothesis "
             "(`mm-nh`), default gate 1 − 10⁻⁶, incremental smoother. Errors after SE(2)/SE(3) alignment (evo's APE); "
             "DA accuracy over the detections with ground truth (docs/metrics.md); real-time factor = data duration "
             "over processing time, on one core of this machine.", ""]

    # Lost in the Woods (Tables I and II analog).
    litw = os.path.join(data, "utias-lost-in-the-woods")
    if os.path.isdir(litw):
        log = os.path.join(scratch, "litw.jsonl")
        convert = [semslam, "convert", "utias-lost-in-the-woods", litw, "--out", log, "--classes", "3",
                   "--misclassification", "0.1", "--keyframe-period", "1"]
        run_checked(convert)
        table, figure = _methods_on_log(semslam, log, "litw", scratch, figures, "Lost in the Woods, 1 s keyframes")
        lines += ["### Lost in the Woods (paper B, Tables I and II analog)", "", "```sh",
                  shown(convert).replace(log, "litw.jsonl"),
                  "for m in known ml gpda mm mm-nh; do build/bin/semslam run --method $m --in litw.jsonl --out litw/$m; done",
                  f"python3 python/plot_methods.py litw/* --out {figure}", "```", ""] + table + [
                  "", f"![trajectories]({os.path.relpath(figure, 'docs')})", ""]
        gate_lines = ["Gate confidence for `mm-nh` on the same log (paper B used 0.9):", "",
                      "| gate | DA accuracy | landmarks (true) | ATE RMSE [m] | time [s] |", "|---|---|---|---|---|"]
        for gate in ["0.9", "0.999", "0.999999"]:
            folder = os.path.join(scratch, "litw-gate", gate)
            run_checked([semslam, "run", "--overwrite", "--method", "mm-nh", "--gate", gate, "--in", log,
                         "--out", folder,
                  "--no-covariances"])
            m = read_metrics(folder)
            gate_lines.append(f"| {gate} | {_number(m.get('da_accuracy'))} | {m.get('landmarks_estimated')} "
                              f"({m.get('landmarks_true')}) | {_number(m.get('ate_rmse'))} | "
                              f"{_number(m.get('time_s'), 1)} |")
        lines += gate_lines + ["", "`build/bin/semslam run --method mm-nh --gate G --in litw.jsonl --out DIR "
                               "--no-covariances`", ""]
        backend_lines = ["Back ends (issue 6): the same runs on the incremental smoother (default) and on the batch "
                         "smoother that re-solves the whole graph at every update:", "",
                         "| method | smoother | ATE RMSE [m] | DA accuracy | time [s] | real-time factor |",
                         "|---|---|---|---|---|---|"]
        duration = _log_duration(log)
        for method in ["known", "mm-nh"]:
            for smoother in ["incremental", "batch"]:
                folder = os.path.join(scratch, "litw-backend", method, smoother)
                run_checked([semslam, "run", "--overwrite", "--method", method, "--smoother", smoother, "--in", log,
                             "--out", folder,
                      "--no-covariances"])
                m = read_metrics(folder)
                backend_lines.append(f"| {method} | {smoother} | {_number(m.get('ate_rmse'))} | "
                                     f"{_number(m.get('da_accuracy'))} | {_number(m.get('time_s'), 2)} | "
                                     f"{_number(duration / m['time_s'], 0)} |")
        lines += backend_lines + ["", "`build/bin/semslam run --method M --smoother S --in litw.jsonl --out DIR "
                                  "--no-covariances`", ""]
    else:
        lines += ["### Lost in the Woods", "", "dataset absent", ""]

    # 3D: Starry Night and the semantic simulator over KITTI 00.
    starry = os.path.join(data, "utias-starry-night")
    if os.path.isdir(starry):
        log = os.path.join(scratch, "starry.jsonl")
        convert = [semslam, "convert", "utias-starry-night", starry, "--out", log, "--classes", "3",
                   "--misclassification", "0.1"]
        run_checked(convert)
        table, figure = _methods_on_log(semslam, log, "starry", scratch, figures, "Starry Night (3D, from above)")
        lines += ["### Starry Night (3D, range-bearing-elevation)", "", "```sh", shown(convert).replace(log, "starry.jsonl"),
                  "for m in known ml gpda mm mm-nh; do build/bin/semslam run --method $m --in starry.jsonl --out starry/$m; done",
                  "```", ""] + table + ["", f"![trajectories]({os.path.relpath(figure, 'docs')})", ""]
    kitti = os.path.join(data, "kitti-odometry-poses", "00.txt")
    if os.path.exists(kitti):
        log = os.path.join(scratch, "kitti00.jsonl")
        simulate = kitti_simulation(semslam, kitti, log)
        run_checked(simulate)
        table, figure = _methods_on_log(semslam, log, "kitti00", scratch, figures,
                                        "semantic simulator over KITTI 00 (3D, from above)")
        lines += ["### Semantic simulator in 3D over KITTI 00", "", "```sh", shown(simulate).replace(log, "kitti00.jsonl"),
                  "for m in known ml gpda mm mm-nh; do build/bin/semslam run --method $m --in kitti00.jsonl --out kitti00/$m; done",
                  "```", ""] + table + ["", f"![trajectories]({os.path.relpath(figure, 'docs')})", ""]
    return lines


# Paper B's robustness study (Fig. 3) on the real logs: noise levels extended until `ml` falls below 90 % DA.
ROBUSTNESS_LOGS = [
    ("Lost in the Woods", "litw", "utias-lost-in-the-woods", "utias-lost-in-the-woods",
     ["--classes", "3", "--misclassification", "0.1", "--keyframe-period", "1"], 150),
    ("MRCLAM Dataset 6, robot 1", "mrclam", "mrclam", "mrclam/MRCLAM_Dataset6",
     ["--robot", "1", "--classes", "3", "--misclassification", "0.1", "--keyframe-period", "1"], 300),
]
ROBUSTNESS_STUDY = ["--methods", ",".join(METHODS), "--odom-noise-scale", "0,1,2,5,10,20",
                    "--misclassification", "0,0.1,0.2,0.3,0.5", "--seeds", "10", "--threads", "2", "--quiet",
                    "--smoother", "batch"]


# Every KITTI simulation of docs/results.md steps over every fifth camera frame (0.5 s, about 4 m at KITTI 00's
# speeds) unless a section says otherwise (the held-out section's other strides).
KITTI_STRIDE = 5


def kitti_simulation(semslam, trajectory, out, seed=None, stride=KITTI_STRIDE):
    """The semantic simulation over a KITTI odometry trajectory of the KITTI 00 results (the simulator's default
    seed, 1, unless `seed` is given; a step every `stride` camera frames)."""
    command = [semslam, "simulate", "semantic", "--dimension", "3", "--trajectory", trajectory, "--trajectory-format",
               "kitti", "--stride", str(stride), "--classes", "3", "--max-range", "30", "--landmark-density", "0.05",
               "--max-offset", "10"]
    return command + (["--seed", str(seed)] if seed is not None else []) + ["--out", out]


def _robustness_table(rows, axis):
    def number(text, digits=3):
        return "–" if text == "" else f"{float(text):.{digits}f}"

    lines = ["| level | method | ATE mean [m] | ATE 95 % CI | DA accuracy | DA 95 % CI | da_accuracy_real | "
             "landmarks | stuck |",
             "|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        if row["axis"] != axis:
            continue
        stuck = "" if row["stuck_fraction"] == "" else f"{float(row['stuck_fraction']):.0%}"
        lines.append(f"| {row['level']} | {row['method']} | {number(row['ate_mean'])} | "
                     f"[{number(row['ate_ci_low'])}, {number(row['ate_ci_high'])}] | {number(row['da_mean'])} | "
                     f"[{number(row['da_ci_low'])}, {number(row['da_ci_high'])}] | {number(row['da_real_mean'])} | "
                     f"{number(row['landmarks_mean'], 1)} | {stuck} |")
    return lines


DA_UNKNOWN = ["ml", "gpda", "mm", "mm-nh"]


def _robustness_readout(by_rule):
    """Paper B's Fig. 3 question, per birth rule: the first level of each sweep at which a method's mean
    da_accuracy_real falls below 0.9, and at how many levels mm-nh has the highest mean da_accuracy_real of the
    DA-unknown methods."""
    lines = ["| birth rule | method | odometry noise: first level < 0.9 | misclassification: first level < 0.9 | "
             "levels where it is the best DA-unknown method |", "|---|---|---|---|---|"]
    for rule, rows in by_rule:
        levels = {}
        for row in rows:
            if row["da_real_mean"] != "":
                levels.setdefault((row["axis"], row["level"]), {})[row["method"]] = float(row["da_real_mean"])
        best = {}
        for (axis, level), means in levels.items():
            candidates = {m: v for m, v in means.items() if m in DA_UNKNOWN}
            if candidates:
                top = max(candidates.values())
                for m, v in candidates.items():
                    if v == top:
                        best[m] = best.get(m, 0) + 1
        for method in [m for m in DA_UNKNOWN if any(row["method"] == m for row in rows)]:
            first = []
            for axis in ("odom_noise", "misclassification"):
                below = [float(level) for (a, level), means in levels.items()
                         if a == axis and method in means and means[method] < 0.9]
                first.append(f"{min(below):g}" if below else "never")
            lines.append(f"| {rule} | {method} | {first[0]} | {first[1]} | {best.get(method, 0)} of {len(levels)} |")
    return lines


def robustness_sections(semslam, data, scratch, shown):
    import csv
    lines = ["## Robustness to odometry noise and misclassification (issue 5, paper B Fig. 3)", "",
             "`semslam study robustness` (docs/robustness-study.md): two one-axis sweeps, odometry noise scale at "
             "misclassification 0.1 and misclassification at noise scale 1, 10 paired seeds per level (every method "
             "on the same perturbed log), on the first N keyframes of each log (N below; the full logs take minutes "
             "per run). ATE is the RMSE after alignment; means with 95 % t-intervals; *stuck*: an mm / mm-nh run "
             "whose ATE exceeds 3× (and 0.1 m more than) known-DA's on the same perturbed log.", ""]
    for title, name, kind, relative, options, steps in ROBUSTNESS_LOGS:
        path = os.path.join(data, relative)
        if not os.path.exists(path):
            lines += [f"### {title}", "", "dataset absent", ""]
            continue
        log = os.path.join(scratch, f"robustness-{name}.jsonl")
        convert = [semslam, "convert", kind, path, "--out", log] + options
        run_checked(convert)
        by_rule = []
        for rule, suffix in (("unassigned", ""), ("threshold", "-threshold")):
            out = os.path.join("docs", "results", "robustness", name + suffix)
            os.makedirs(out, exist_ok=True)
            study = [semslam, "study", "robustness", "--log", log, "--max-steps", str(steps), "--out", out,
                     "--overwrite", "--birth", rule] + ROBUSTNESS_STUDY
            summary = run_checked(study).strip()
            plot = [sys.executable, os.path.join(HERE, "plot_robustness.py"), out, "--metrics",
                    "ate_rmse,rot_rmse,da_accuracy,da_accuracy_real"]
            run_checked(plot)
            with open(os.path.join(out, "robustness_summary.csv")) as f:
                rows = list(csv.DictReader(f))
            by_rule.append((rule, rows))
            heading = f"### {title}, first {steps} keyframes, `--birth {rule}`" + (
                " (the default)" if rule == "unassigned" else " (paper B's rule)")
            lines += [heading, "", "```sh", shown(convert).replace(log, f"{name}.jsonl"),
                      shown(study).replace(log, f"{name}.jsonl"),
                      " ".join(["python3"] + plot[1:]).replace(HERE + "/", "python/"),
                      "```", "", f"`{summary.replace(log, name + '.jsonl')}`", "",
                      f"![box plots]({os.path.relpath(out, 'docs')}/robustness.png)", "", "Odometry noise scale:", ""]
            lines += _robustness_table(rows, "odom_noise") + ["", "Misclassification rate:", ""]
            lines += _robustness_table(rows, "misclassification") + [""]
        lines += [f"### {title}: where each method falls below 90 % `da_accuracy_real` (paper B's Fig. 3 question)",
                  "", "The first level of each sweep whose mean `da_accuracy_real` over the seeds is below 0.9, and "
                  "how many of the sweeps' levels each DA-unknown method leads (highest mean `da_accuracy_real`; ties "
                  "count for each), with the default birth rule and paper B's beside it.", ""]
        lines += _robustness_readout(by_rule) + [""]
    return lines
