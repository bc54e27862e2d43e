#!/usr/bin/env python3
"""Regenerate docs/results.md: every measured figure of the project, each with the command that produced it.

Usage: make_results.py [--build BUILD_DIR] [--data DATA_DIR] [--out docs/results.md]

Each section runs the `semslam` tool on the shared datasets (../shared/data beside the repository) and tabulates
its JSON reports. A section whose data is absent says so instead of inventing numbers.
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import tempfile

import plot_hybrid
import results_assignment_score
import results_association
import results_association_oracles
import results_association_ceiling
import results_backends
import results_commands
import results_association_defaults
import results_hybrid_mrclam
import results_held_out_trajectories
import results_hybrid_scaling
import results_kitti_tracking
import results_loop_closure_branches
import results_loop_closure_next_best
import results_loop_closure_open_splits
import results_max_mixtures
import results_studies_mpi

POSE_GRAPHS = [
    ("manhattan (2D)", "vertigo/manhattan/originalDataset/g2o/manhattanOlson3500.g2o", "g2o", 146.07873),
    ("intel (2D)", "vertigo/intel/originalDataset/intel.g2o", "g2o", 546.46312),
    ("ring (2D)", "vertigo/ring/originalDataset/ring.g2o", "g2o", 11.163101),
    ("sphere2500 (3D)", "vertigo/sphere2500/originalDataset/sphere2500.g2o", "g2o", 1351.4019),
    ("city10000 (2D)", "vertigo/city10000/originalDataset/city10000.g2o", "g2o", None),
    ("cityTrees10000 (2D, landmarks)", "isam/cityTrees10000.txt", "isam", None),
]

EVO_CASES = [
    ("KITTI 00 ORB, APE, SE(3)", "ate", "KITTI_00_ORB.txt", "KITTI_00_gt.txt", "kitti", ["--align", "se3"],
     1.3034497),
    ("KITTI 00 S-PTAM, APE, SE(3)", "ate", "KITTI_00_SPTAM.txt", "KITTI_00_gt.txt", "kitti", ["--align", "se3"],
     3.7384879),
    ("KITTI 00 ORB, RPE 10 m", "rpe", "KITTI_00_ORB.txt", "KITTI_00_gt.txt", "kitti",
     ["--delta", "10", "--delta-unit", "m"], 0.2262613),
    ("KITTI 00 S-PTAM, RPE 10 m", "rpe", "KITTI_00_SPTAM.txt", "KITTI_00_gt.txt", "kitti",
     ["--delta", "10", "--delta-unit", "m"], 0.2760711),
    ("fr2_desk ORB, APE, SE(3), 0.01 s", "ate", "fr2_desk_ORB.txt", "fr2_desk_groundtruth.txt", "tum",
     ["--align", "se3", "--t-max-diff", "0.01"], 0.00811898),
]


def run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"make_results.py: {' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    return result.stdout


# The binary the sections run (--build), shown to the reader as the quick start's build/bin/semslam: a build in a
# scratch folder must not leak its path into docs/results.md.
SEMSLAM_RUN = os.path.join("build", "bin", "semslam")
SEMSLAM_SHOWN = "build/bin/semslam"


def shown(command, data):
    """The command as a reader would type it from the repository root."""
    text = " ".join(command).replace(SEMSLAM_RUN, SEMSLAM_SHOWN)
    return text.replace(data, "../shared/data").replace(os.getcwd() + "/", "")


def pose_graph_section(semslam, data, scratch):
    lines = ["## Pose-graph optimisation (issue 2)", "",
             "Batch Gauss-Newton (`gn`) and Levenberg-Marquardt (`lm`) from each file's initial values, first pose "
             "held by a prior of σ = 1e-6; chi2 over the file's own edges; the gradient is the max-norm of the "
             "exact gradient at the result and at the start. Times are wall-clock on this machine, single run "
             "(see `make bench` for medians and the comparison with Ceres).", "",
             "| graph | solver | final chi2 | reference optimum | iterations | time [s] | gradient / initial |",
             "|---|---|---|---|---|---|---|"]
    commands = []
    for name, relative, fmt, optimum in POSE_GRAPHS:
        path = os.path.join(data, relative)
        if not os.path.exists(path):
            lines.append(f"| {name} | – | dataset absent | | | | |")
            continue
        for solver in ("gn", "lm"):
            report = os.path.join(scratch, f"{os.path.basename(relative)}.{solver}.json")
            command = [semslam, "optimize", path, "--format", fmt, "--solver", solver, "--report", report]
            run(command)
            commands.append(shown(command, data).replace(report, "report.json"))
            r = json.load(open(report))
            ratio = r["final_gradient_norm"] / r["initial_gradient_norm"]
            reference = f"{optimum:.8g}" if optimum else "–"
            lines.append(f"| {name} | {solver} | {r['final_chi2']:.8f} | {reference} | {r['iterations']} | "
                         f"{r['time_s']:.3f} | {ratio:.1e} |")
    lines += ["", "Commands:", "", "```sh"] + commands + ["```", ""]

    path = os.path.join(data, POSE_GRAPHS[0][1])
    if os.path.exists(path):
        report = os.path.join(scratch, "manhattan_marginal.json")
        command = [semslam, "optimize", path, "--marginals", "3498,3499", "--report", report]
        run(command)
        r = json.load(open(report))
        last = r["marginals"]["3499"]
        lines += ["Marginal covariance of manhattan's last pose (id 3499) at the Gauss-Newton optimum, in the "
                  "(x, y, θ) tangent:", "",
                  f"diag = ({last[0][0]:.6f}, {last[1][1]:.6f}, {last[2][2]:.7f}); reference "
                  "diag(82.0644, 185.3390, 0.432252).", "",
                  "```sh", shown(command, data).replace(report, "report.json"), "```", ""]
    return lines


def evo_section(semslam, data):
    lines = ["## Trajectory evaluation against evo's published numbers (issue 3)", "",
             "| case | rmse | evo | difference |", "|---|---|---|---|"]
    commands = []
    folder = os.path.join(data, "evo-testdata")
    if not os.path.isdir(folder):
        return lines + ["", "evo-testdata absent.", ""]
    for name, metric, est, ref, fmt, options, expected in EVO_CASES:
        command = [semslam, "eval", metric, "--est", os.path.join(folder, est), "--ref", os.path.join(folder, ref),
                   "--format", fmt] + options + ["--json"]
        r = json.loads(run(command))
        commands.append(shown(command, data))
        lines.append(f"| {name} | {r['rmse']:.9f} | {expected} | {abs(r['rmse'] - expected):.1e} |")
    return lines + ["", "Commands:", "", "```sh"] + commands + ["```", ""]


CONVERSIONS = [
    ("utias-lost-in-the-woods", "utias-lost-in-the-woods", []),
    ("utias-starry-night", "utias-starry-night", []),
    ("mrclam", "mrclam/MRCLAM_Dataset6", ["--robot", "1"]),
    ("isam", "isam/cityTrees10000.txt", []),
]


def datasets_section(semslam, data, scratch):
    lines = ["## Real datasets as measurement logs (issue 3)", "",
             "Each dataset converted at full rate, then its detections and odometry compared with the true-model "
             "prediction from the ground truth (docs/datasets.md explains every column and decision).", ""]
    for kind, relative, options in CONVERSIONS:
        path = os.path.join(data, relative)
        if not os.path.exists(path):
            lines += [f"### {kind}", "", "dataset absent", ""]
            continue
        log = os.path.join(scratch, kind + ".jsonl")
        convert = [semslam, "convert", kind, path, "--out", log] + options
        summary = run(convert).strip()
        check = [semslam, "check", log, "--residuals"]
        residuals = run(check)
        table = residuals[residuals.find("residuals against"):].rstrip()
        lines += [f"### {kind}", "", "```sh", shown(convert, data).replace(log, kind + ".jsonl"),
                  shown(check, data).replace(log, kind + ".jsonl"), "```", "", "```",
                  summary.replace(log, kind + ".jsonl"), table, "```", ""]
    return lines


def hybrid_study_lines(title, command, output, analysis, data, out):
    """One study's table: per metric the pooled paired comparison and on how many layouts it separates; the NEES
    subsets and the disambiguation rates."""
    a = analysis
    layouts = a["layouts"]
    lines = [f"### {title}", "", "```sh", shown(command, data).replace(out, "DIR"), "```", "", "```", output, "```",
             "", f"{layouts} layout(s), {a['tracks']} paired tracks, alpha = {a['alpha']:g}.", "",
             "| metric | classifier | geometric | paired difference (pooled) | 95 % bootstrap CI | excludes 0 | "
             "Wilcoxon p (classifier lower) | pairs that differ | layouts separating |",
             "|---|---|---|---|---|---|---|---|---|"]
    for metric, _ in plot_hybrid.METRICS:
        p = a["paired"][metric]
        lines.append(f"| {metric} | {p['classifier_mean']:.4g} | {p['geometric_mean']:.4g} | "
                     f"{p['mean_difference']:.4g} | [{p['ci_low']:.4g}, {p['ci_high']:.4g}] | "
                     f"{'yes' if p['excludes_zero'] else 'no'} | {p['p_less']:.2g} | {p['nonzero']} | "
                     f"{p['layouts_separating']} of {layouts} |")
    lines.append("")
    for model in ("classifier", "geometric"):
        d = a["disambiguated"][model]
        parts = []
        for subset, label in (("heaviest", "heaviest component"), ("heaviest_correct", "its history correct"),
                              ("heaviest_wrong", "its history wrong"), ("mixture", "moment-matched mixture")):
            n = a["nees"][model].get(subset)
            if n and n["count"] > 0:
                parts.append(f"{label} {n['mean']:.3g} (n = {n['count']}, band [{n['lower']:.3g}, {n['upper']:.3g}], "
                             f"{'inside' if n['inside'] else ('below' if n['mean'] < n['lower'] else 'above')})")
        per_layout = ", ".join(f"{100 * v:.0f}" for _, v in sorted(d["heaviest_correct_per_layout"].items()))
        lines.append(f"- {model}: heaviest final history correct in {100 * d['heaviest_correct']:.1f} % of tracks "
                     f"(per layout, %: {per_layout}); one history > 0.9 at step 5 in {100 * d['fraction']:.0f} %; "
                     f"final-pose NEES: " + "; ".join(parts) + ".")
    lines.append(f"- largest gate lost mass per run: {a['gate_lost_mass_max']:.3g}; sampled-vs-linearised total "
                 "variation of the weights (mean over steps and runs): "
                 f"{a['sampled_vs_analytic_total_variation']:.3g}; "
                 f"{a['sampled_candidates']:.0f} weights sampled in {a['sampling_s']:.2f} s of sampling (thread time), "
                 f"total run time {a['run_s_total']:.1f} s (thread time).")
    if "entropy_slope" in a:
        e = a["entropy_slope"]
        side = "below zero" if e["below_zero"] else "not below zero"
        lines.append(f"- paired slope of the classifier's entropy against alpha {e['mean']:.4g}, 95 % bootstrap CI "
                     f"[{e['ci_low']:.4g}, {e['ci_high']:.4g}] ({side}).")
    return lines + [""]


def hybrid_section(semslam, data, scratch, python):
    """Paper A's study on generated aliased2d layouts (issues 4 and 12) and the hybrid belief on Lost in the Woods."""
    lines = ["## Hybrid belief, paper A (issues 4 and 12)", "",
             "docs/hybrid-belief.md explains the method and every decision. Study (`semslam study hybrid`): 10 "
             "generated layouts (sim/Aliased2dLayout.h, layout seeds 1-10; docs/simulators.md) × 50 tracks of 10 "
             "steps, every track run with and without the classifier model on the same log (paired), 1000 samples "
             "per weight, pruning at w_max/150, gate at 1e5. Differences are classifier − geometric at the final "
             "step; intervals are stratified paired bootstrap 95 % intervals (resampling tracks within layouts), "
             "p-values one-sided Wilcoxon signed-rank (python/paired_statistics.py: the error differences are "
             "bimodal, mostly 0 with a few of metres, so a t interval is the wrong tool); a layout separates when "
             "its own interval excludes 0 on the pooled mean's side. NEES bands are the χ² 95 % bands of the mean "
             "over the runs counted.", ""]
    studies = [
        ("alpha = 0.25, sampled weights (the default study)", ["--alpha", "0.25"]),
        ("alpha = 0.25, sampled weights, 200 tracks per layout", ["--alpha", "0.25", "--tracks", "200"]),
        ("alpha = 0.25, sampled weights, 10 held-out layouts (seeds 1001-1010, never looked at during development)",
         ["--alpha", "0.25", "--layout-seed", "1001"]),
        ("alpha = 0.25, importance weights", ["--alpha", "0.25", "--weights", "importance"]),
        ("alpha = 0.25, analytic weights", ["--alpha", "0.25", "--weights", "analytic"]),
        ("stress test: the parking aisle (three bays 6 m apart), sampled weights",
         ["--alpha", "0.25", "--scenario", os.path.join("data", "scenarios", "aliased2d_default.json")]),
        ("stress test: four bays 5 m apart, sampled weights",
         ["--alpha", "0.25", "--scenario", os.path.join("data", "scenarios", "aliased2d_four_bays.json")]),
        ("consistency check: the default study with the first pose's prior mean drawn from its prior",
         ["--alpha", "0.25", "--pose-mean", "sampled"]),
    ]
    for index, (title, flags) in enumerate(studies):
        out = os.path.join(scratch, f"hybrid-study-{index}")
        command = [semslam, "study", "hybrid"] + flags + ["--out", out, "--overwrite", "--quiet"]
        output = run(command).strip().replace(out, "DIR")
        lines += hybrid_study_lines(title, command, output, plot_hybrid.analyze(out, 0.25), data, out)
    sweep = os.path.join(scratch, "hybrid-sweep")
    command = [semslam, "study", "hybrid", "--out", sweep, "--overwrite", "--quiet"]
    output = run(command).strip().replace(sweep, "DIR")
    e = plot_hybrid.analyze(sweep, 0.25)["entropy_slope"]
    lines += ["### alpha sweep (Fig. 5 analog), sampled weights", "", "```sh",
              shown(command, data).replace(sweep, "DIR"), "```", "", "```", output, "```", "",
              f"Paired slope of the classifier's entropy against alpha {e['mean']:.4g}, 95 % bootstrap CI "
              f"[{e['ci_low']:.4g}, {e['ci_high']:.4g}] ({'below zero' if e['below_zero'] else 'not below zero'}). "
              "The figure shows all four metrics at every alpha.", ""]
    figures = os.path.join("docs", "figures")
    os.makedirs(figures, exist_ok=True)
    run([python, os.path.join("python", "plot_hybrid.py"), "fig5", sweep, "--out",
         os.path.join(figures, "hybrid_fig5.png")])
    track = os.path.join(scratch, "track.jsonl")
    run([semslam, "simulate", "aliased2d", "--layout-seed", "1", "--steps", "10", "--seed", "3", "--out", track,
         "--overwrite"])
    runs = {}
    for method in ("hybrid", "hybrid-geometric"):
        runs[method] = os.path.join(scratch, method)
        run([semslam, "run", "--overwrite", "--method", method, "--in", track, "--out", runs[method], "--seed", "1"])
    run([python, os.path.join("python", "plot_hybrid.py"), "fig4", runs["hybrid"], runs["hybrid-geometric"],
         "--steps", "4,5,7,9", "--out", os.path.join(figures, "hybrid_fig4.png")])
    lines += ["Figures: `docs/figures/hybrid_fig4.png` (Fig. 4 analog on generated layout 1, `semslam simulate "
              "aliased2d --layout-seed 1 --steps 10 --seed 3`, then `semslam run --method hybrid|hybrid-geometric "
              "--seed 1`, `python/plot_hybrid.py fig4`), `docs/figures/hybrid_fig5.png` (Fig. 5 analog from the alpha "
              "sweep, `python/plot_hybrid.py fig5`).", ""]

    litw = os.path.join(data, "utias-lost-in-the-woods")
    lines += ["### Lost in the Woods, first 120 keyframes (1 Hz)", ""]
    if not os.path.exists(litw):
        return lines + ["dataset absent", ""]
    log = os.path.join(scratch, "litw.jsonl")
    convert = [semslam, "convert", "utias-lost-in-the-woods", litw, "--out", log, "--classes", "2",
               "--keyframe-period", "1", "--max-steps", "120", "--map-prior", "0.1", "--initial-pose-sigma",
               "1,1,0.3"]
    run(convert)
    lines += ["```sh", shown(convert, data).replace(log, "litw.jsonl"), "```", "",
              "| method | weights | ATE rmse [m] | DA accuracy | NEES (heaviest) | entropy | components max/mean | time [s] |",
              "|---|---|---|---|---|---|---|---|"]
    for method in ("hybrid", "hybrid-geometric"):
        for weights in ("sampled", "importance", "analytic"):
            out = os.path.join(scratch, f"litw-{method}-{weights}")
            command = [semslam, "run", "--overwrite", "--method", method, "--weights", weights, "--branching",
                       "one-at-a-time", "--max-components", "20", "--in", log, "--out", out]
            run(command)
            with open(os.path.join(out, "metrics.json")) as f:
                m = json.load(f)
            counts = [len(json.loads(line)["components"]) for line in open(os.path.join(out, "hypotheses.jsonl"))]
            lines.append(f"| {method} | {weights} | {m['ate_rmse']:.4g} | {m['da_accuracy']:.4g} | {m['nees_mean']:.4g} | "
                         f"{m['entropy']:.3g} | {max(counts)}/{sum(counts) / len(counts):.2f} | {m['time_s']:.2f} |")
    lines += ["", "Command: `semslam run --method M --weights W --branching one-at-a-time --max-components 20 "
              "--in litw.jsonl --out DIR`.", ""]
    lines += bounded_memory_lines(semslam, data, scratch, litw)
    return lines


def bounded_memory_lines(semslam, data, scratch, litw):
    """The hybrid belief with its defaults on a log where whole-association branching would not fit in memory
    (docs/hybrid-belief.md, "Bounded memory")."""
    log = os.path.join(scratch, "litw200.jsonl")
    convert = [semslam, "convert", "utias-lost-in-the-woods", litw, "--out", log, "--classes", "2",
               "--keyframe-period", "1", "--max-steps", "200", "--map-prior", "0.1", "--initial-pose-sigma",
               "1,1,0.3"]
    run(convert)
    out = os.path.join(scratch, "litw200-hybrid")
    command = [semslam, "run", "--method", "hybrid", "--in", log, "--out", out, "--no-covariances", "--quiet",
               "--overwrite"]
    stderr, peak, wall = results_commands.peak_memory_run(command)
    with open(os.path.join(out, "metrics.json")) as f:
        m = json.load(f)
    note = next((line for line in stderr.splitlines() if line.startswith("note:")), "no bound bound")
    return ["### Bounded memory: Lost in the Woods, first 200 keyframes, the hybrid belief's defaults", "",
            "```sh", shown(convert, data).replace(log, "litw200.jsonl"),
            shown(command, data).replace(log, "litw200.jsonl").replace(out, "DIR"), "```", "",
            f"Peak resident memory {peak:.0f} MiB, wall time {wall:.1f} s (issue 12 reports the former defaults, "
            f"whole-association branching without a cap, using all 24 GB on a log of this kind); ATE {m['ate_rmse']:.4g} m, "
            f"DA accuracy {m['da_accuracy']:.4g}, {m.get('components', '?')} component(s) at the end. What the run "
            "said:", "", "```", note, "```", ""]


SECTIONS = ["pose-graphs", "evo", "datasets", "hybrid", "hybrid-mrclam", "hybrid-scaling", "max-mixtures",
            "robustness", "association", "held-out-trajectories", "association-oracles", "association-ceiling", "association-defaults",
            "loop-closure-branches",
            "loop-closure-next-best", "loop-closure-open-splits", "assignment-score", "kitti-tracking", "back-ends",
            "studies-mpi"]


def section_lines(name, semslam, data, scratch):
    """One section's lines, wrapped in markers so that --only can regenerate it alone."""
    if name == "pose-graphs":
        body = pose_graph_section(semslam, data, scratch)
    elif name == "evo":
        body = evo_section(semslam, data)
    elif name == "datasets":
        body = datasets_section(semslam, data, scratch)
    elif name == "hybrid":
        body = hybrid_section(semslam, data, scratch, sys.executable)
    elif name == "max-mixtures":
        body = results_max_mixtures.max_mixture_sections(semslam, data, scratch,
                                                         lambda command: shown(command, data))
    elif name == "robustness":
        body = results_max_mixtures.robustness_sections(semslam, data, scratch, lambda command: shown(command, data))
    elif name == "association":
        body = results_association.association_section(semslam, data, scratch, lambda command: shown(command, data))
    elif name == "association-oracles":
        body = results_association_oracles.association_oracles_section(semslam, data, scratch,
                                                                       lambda command: shown(command, data))
    elif name == "association-ceiling":
        body = results_association_ceiling.association_ceiling_section(semslam, data, scratch,
                                                                       lambda command: shown(command, data),
                                                                       sys.executable)
    elif name == "association-defaults":
        body = results_association_defaults.association_defaults_section(semslam, data, scratch)
    elif name == "loop-closure-branches":
        body = results_loop_closure_branches.loop_closure_branches_section(semslam, data, scratch,
                                                                           lambda command: shown(command, data),
                                                                           sys.executable)
    elif name == "loop-closure-next-best":
        body = results_loop_closure_next_best.loop_closure_next_best_section(semslam, data, scratch,
                                                                             lambda command: shown(command, data))
    elif name == "loop-closure-open-splits":
        body = results_loop_closure_open_splits.loop_closure_open_splits_section(semslam, data, scratch,
                                                                                 lambda command: shown(command, data))
    elif name == "held-out-trajectories":
        body = results_held_out_trajectories.held_out_trajectories_section(
            semslam, data, os.path.join(scratch, "held-out-trajectories"), lambda command: shown(command, data))
    elif name == "assignment-score":
        body = results_assignment_score.assignment_score_section(semslam, data, scratch,
                                                                 lambda command: shown(command, data))
    elif name == "kitti-tracking":
        body = results_kitti_tracking.kitti_tracking_section(semslam, data, scratch,
                                                             lambda command: shown(command, data), sys.executable)
    elif name == "back-ends":
        body = results_backends.backends_section(semslam, data, scratch, lambda command: shown(command, data))
    elif name == "hybrid-scaling":
        body = results_hybrid_scaling.hybrid_scaling_section(semslam, data, scratch, lambda command: shown(command, data))
    elif name == "hybrid-mrclam":
        body = results_hybrid_mrclam.hybrid_mrclam_section(semslam, data, scratch, lambda command: shown(command, data))
    elif name == "studies-mpi":
        body = results_studies_mpi.studies_mpi_section(semslam, data, scratch, lambda command: shown(command, data))
    else:
        sys.exit(f"make_results.py: unknown section {name} ({', '.join(SECTIONS)})")
    return [f"<!-- section:{name} -->"] + body + [f"<!-- end:{name} -->", ""]


# Sections measured by other commands than this script (each section says which: `make fuzz` for hostile-input,
# an hour and more of fuzzing): a full regeneration keeps them as they are in the existing file.
KEPT_SECTIONS = ["hostile-input"]


def kept_section(text, name):
    """Section `name` of an existing results.md, markers included, as lines (empty when it has none)."""
    begin, end = f"<!-- section:{name} -->", f"<!-- end:{name} -->"
    if begin not in text or end not in text:
        return []
    return (begin + text.split(begin, 1)[1].split(end, 1)[0] + end).split("\n") + [""]


def splice(text, name, lines):
    """Replaces section `name` of an existing results.md. A section the file does not hold yet goes where a full
    regeneration would put it: before the first later section (SECTIONS, then KEPT_SECTIONS) the file holds, or at
    the end."""
    begin, end = f"<!-- section:{name} -->", f"<!-- end:{name} -->"
    if begin in text and end in text:
        head, rest = text.split(begin, 1)
        tail = rest.split(end, 1)[1].lstrip("\n")
        return head + "\n".join(lines) + tail
    order = SECTIONS + KEPT_SECTIONS
    for later in order[order.index(name) + 1:]:
        marker = f"<!-- section:{later} -->"
        if marker in text:
            head, tail = text.split(marker, 1)
            return head + "\n".join(lines) + "\n" + marker + tail
    return text.rstrip("\n") + "\n\n" + "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--build", default="build")
    parser.add_argument("--data", default=os.path.join("..", "shared", "data"))
    parser.add_argument("--out", default=os.path.join("docs", "results.md"))
    parser.add_argument("--only", action="append", choices=SECTIONS,
                        help="regenerate only this section of the existing file (repeatable)")
    args = parser.parse_args()
    global SEMSLAM_RUN
    semslam = SEMSLAM_RUN = os.path.join(args.build, "bin", "semslam")
    data = os.path.abspath(args.data)
    if not os.path.exists(semslam):
        sys.exit(f"make_results.py: {semslam} not found: build first (make build)")

    with tempfile.TemporaryDirectory() as scratch:
        if args.only:
            with open(args.out) as f:
                text = f.read()
            for name in args.only:
                text = splice(text, name, section_lines(name, semslam, data, scratch))
        else:
            lines = ["# Measured results", "",
                     "Regenerated by `make results` (python/make_results.py; one section: `--only NAME`); do not "
                     f"edit by hand. Machine: {platform.machine()}, {os.cpu_count()} cores; generated "
                     f"{datetime.date.today().isoformat()}.", ""]
            for name in SECTIONS:
                lines += section_lines(name, semslam, data, scratch)
            existing = open(args.out).read() if os.path.exists(args.out) else ""
            for name in KEPT_SECTIONS:
                lines += kept_section(existing, name)
            text = "\n".join(lines)
    with open(args.out + ".tmp", "w") as out:
        out.write(text)
    os.replace(args.out + ".tmp", args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
