"""docs/results.md section of issue 12: the hybrid belief's memory on a long real log, and the hybrid belief in 3D;
used by make_results.py.

Memory: MRCLAM Dataset 6, robot 1, the first 300 keyframes with the map prior (the hybrid-mrclam section's log),
with the defaults (1000 components, --max-memory 2048 MiB), with 100 components, and with a memory budget small
enough to bind (--max-memory 64). Peak resident memory is the process's own (getrusage of a fresh child), wall
times are one run each on the 2-core machine while other work ran beside it; the
component estimate is the belief's (Smoother::memoryBytes, docs/hybrid-belief.md, "Bounded memory").

3D: UTIAS Starry Night (a stereo camera's range-bearing-elevation detections of 20 point landmarks; 3 classes from
the landmark ids with 10 % misclassification, the categorical model; 1 Hz keyframes; the map prior of sigma 0.1 m)
and 20 generated layouts of paper A's scenario lifted to 3D with the objects at heights 0, 0.4 and 0.8 m
(`simulate aliased2d --object-heights`).
"""
import json
import os

from results_commands import peak_memory_run, read_metrics, run_checked

MRCLAM_CONVERT = ["--robot", "1", "--classes", "3", "--misclassification", "0.1", "--keyframe-period", "1",
                  "--map-prior", "0.1", "--max-steps", "300"]
MEMORY_RUNS = [("defaults", []), ("100 components", ["--max-components", "100"]),
               ("--max-memory 64", ["--max-memory", "64"])]
STARRY_CONVERT = ["--classes", "3", "--misclassification", "0.1", "--keyframe-period", "1", "--max-steps", "200",
                  "--map-prior", "0.1"]
STARRY_METHODS = ["known", "mm-nh", "hybrid", "hybrid-geometric"]
TRACKS_3D = 20


def _note(stderr):
    return next((line for line in stderr.splitlines() if line.startswith("note:")), "no bound bound")


def _components(folder):
    path = os.path.join(folder, "hypotheses.jsonl")
    if not os.path.exists(path):
        return "1/1.0"
    counts = [len(json.loads(line)["components"]) for line in open(path) if line.strip()]
    return f"{max(counts)}/{sum(counts) / len(counts):.1f}"


def _memory_lines(semslam, data, scratch, shown):
    dataset = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    if not os.path.exists(dataset):
        return ["MRCLAM absent", ""]
    log = os.path.join(scratch, "mrclam-map-1-300.jsonl")
    convert = [semslam, "convert", "mrclam", dataset, "--out", log] + MRCLAM_CONVERT
    run_checked(convert)
    lines = ["### Memory on a long real log: MRCLAM robot 1, 300 keyframes, map prior", "",
             "```sh", shown(convert).replace(log, "mrclam-300.jsonl")]
    rows, notes = [], []
    for name, flags in MEMORY_RUNS:
        out = os.path.join(scratch, "mrclam-300-" + name.replace(" ", "-").replace("-", ""))
        command = [semslam, "run", "--method", "hybrid", "--in", log, "--out", out, "--no-covariances", "--quiet",
                   "--overwrite"] + flags
        lines.append(shown(command).replace(log, "mrclam-300.jsonl").replace(out, "DIR"))
        stderr, peak, wall = peak_memory_run(command)
        m = read_metrics(out)
        reports = [json.loads(line)["report"] for line in open(os.path.join(out, "hypotheses.jsonl"))]
        memory_capped = sum(1 for r in reports if r["memory_capped_components"] > 0)
        rows.append(f"| {name} | {peak:.0f} | {wall:.0f} | {_components(out)} | {memory_capped} | "
                    f"{m['ate_rmse']:.3f} | {m.get('da_accuracy_real', float('nan')):.3f} |")
        notes.append(f"- {name}: `{_note(stderr)}`")
    lines += ["```", "", "| run | peak memory [MiB] | wall [s] | components max/mean | steps the memory bound "
              "bound | ATE rmse [m] | da_accuracy_real |", "|---|---|---|---|---|---|---|"] + rows + ["", *notes, ""]
    return lines


def _starry_lines(semslam, data, scratch, shown):
    dataset = os.path.join(data, "utias-starry-night")
    if not os.path.exists(dataset):
        return ["Starry Night absent", ""]
    log = os.path.join(scratch, "starry-map.jsonl")
    convert = [semslam, "convert", "utias-starry-night", dataset, "--out", log] + STARRY_CONVERT
    run_checked(convert)
    lines = ["### 3D: Starry Night with a map prior, the categorical model", "", "```sh",
             shown(convert).replace(log, "starry-map.jsonl")]
    rows = []
    for method in STARRY_METHODS:
        out = os.path.join(scratch, f"starry-map-{method}")
        command = [semslam, "run", "--method", method, "--in", log, "--out", out, "--no-covariances", "--quiet",
                   "--overwrite"]
        lines.append(shown(command).replace(log, "starry-map.jsonl").replace(out, "DIR"))
        _, peak, wall = peak_memory_run(command)
        m = read_metrics(out)
        rows.append(f"| {method} | {m['ate_rmse']:.3f} | {m.get('da_accuracy_real', float('nan')):.3f} | "
                    f"{m.get('landmarks_estimated', '?')} | {_components(out)} | {wall:.1f} | {peak:.0f} |")
    lines += ["```", "", "| method | ATE rmse [m] | da_accuracy_real | landmarks | components max/mean | wall [s] | "
              "peak memory [MiB] |", "|---|---|---|---|---|---|---|"] + rows + [""]
    return lines


def _aliased3d_lines(semslam, scratch, shown):
    """Generated layout S, track 0 of seed S, for S = 1..TRACKS_3D, lifted with the objects at three heights; both
    models, sampled weights."""
    rows = {"hybrid": [], "hybrid-geometric": []}
    commands = []
    for seed in range(1, TRACKS_3D + 1):
        log = os.path.join(scratch, f"aliased3d-{seed}.jsonl")
        simulate = [semslam, "simulate", "aliased2d", "--layout-seed", str(seed), "--steps", "10", "--seed",
                    str(seed), "--object-heights", "0,0.4,0.8,0,0.4,0.8", "--out", log]
        run_checked(simulate)
        for method in rows:
            out = os.path.join(scratch, f"aliased3d-{seed}-{method}")
            command = [semslam, "run", "--method", method, "--in", log, "--out", out, "--quiet", "--overwrite"]
            if seed == 1:
                commands.append(shown(command).replace(log, "aliased3d-S.jsonl").replace(out, "DIR"))
            run_checked(command)
            m = read_metrics(out)
            final = [json.loads(line) for line in open(os.path.join(out, "hypotheses.jsonl"))][-1]["metrics"]
            rows[method].append((final["entropy"], m["ate_rmse"], m["da_accuracy"]))
        if seed == 1:
            commands.insert(0, shown(simulate).replace(log, "aliased3d-S.jsonl").replace(" 1 ", " S "))
    lines = [f"### 3D: paper A's scenario with the objects at three heights, {TRACKS_3D} tracks", "",
             f"Generated layout S (paper A's six objects, docs/simulators.md) and its track for S = 1 to {TRACKS_3D}, "
             "10 steps each, sampled weights (the defaults):", "",
             "```sh", *commands, "```", "",
             "| method | final entropy, mean | tracks with final entropy > 0.1 | ATE rmse, mean [m] | "
             "DA accuracy, mean |", "|---|---|---|---|---|"]
    for method, values in rows.items():
        n = len(values)
        lines.append(f"| {method} | {sum(v[0] for v in values) / n:.3f} | {sum(v[0] > 0.1 for v in values)} | "
                     f"{sum(v[1] for v in values) / n:.3f} | {sum(v[2] for v in values) / n:.3f} |")
    return lines + [""]


def hybrid_scaling_section(semslam, data, scratch, shown):
    lines = ["## Hybrid belief: bounded memory and 3D (issue 12)", "",
             " ".join(__doc__.split("\n\n", 1)[1].split()), ""]
    lines += _memory_lines(semslam, data, scratch, shown)
    lines += _starry_lines(semslam, data, scratch, shown)
    lines += _aliased3d_lines(semslam, scratch, shown)
    return lines
