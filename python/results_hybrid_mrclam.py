"""docs/results.md section of issue 12: the hybrid belief as a multi-hypothesis contender on MRCLAM Dataset 6, every
robot, with a map prior (paper A's known but uncertain map), against mm-nh given the same prior and against known
association; used by make_results.py.

The logs are the association section's (3 classes, 10 % misclassification, 1 Hz keyframes) with the landmark ground
truth as a prior map of sigma 0.1 m (`--map-prior 0.1`). The hybrid belief knows the number of objects and has no
births or clutter hypothesis (paper A): a detection of another robot (MRCLAM's clutter) must go to a landmark or,
when no jointly compatible association takes it, is dropped. It runs with one-detection-at-a-time branching and 20
components: the time of a step grows with the components (each is weighed, branched and updated), and with its
defaults (1000 components) 300 keyframes of robot 1 take about ten minutes (section "Hybrid belief: bounded memory
and 3D"), the 888 of a whole log hours per robot. Two runs at a time on the 2-core machine; the time per step is
the run's time over its steps.
"""
import concurrent.futures
import json
import os

from results_commands import read_metrics, run_checked

ROBOTS = [1, 2, 3, 4, 5]
CONVERT = ["--classes", "3", "--misclassification", "0.1", "--keyframe-period", "1", "--map-prior", "0.1"]
HYBRID = ["--branching", "one-at-a-time", "--max-components", "20"]
METHODS = [("known", []), ("mm-nh", []), ("hybrid", HYBRID), ("hybrid-geometric", HYBRID)]


def _components(folder):
    """Components held per step (hypotheses.jsonl): max and mean; (1, 1) for a single-hypothesis method."""
    path = os.path.join(folder, "hypotheses.jsonl")
    if not os.path.exists(path):
        return 1, 1.0
    counts = [len(json.loads(line)["components"]) for line in open(path) if line.strip()]
    return max(counts), sum(counts) / len(counts)


def _run(semslam, log, steps, method, flags, out):
    run_checked([semslam, "run", "--method", method, "--in", log, "--out", out, "--no-covariances", "--quiet",
                 "--overwrite"] + flags)
    m = read_metrics(out)
    most, mean = _components(out)
    return {"ate": m["ate_rmse"], "da_real": m.get("da_accuracy_real", float("nan")),
            "precision": m.get("pairwise_precision", float("nan")), "recall": m.get("pairwise_recall", float("nan")),
            "time_per_step_ms": 1000.0 * m["time_s"] / steps, "components": f"{most}/{mean:.1f}"}


def hybrid_mrclam_section(semslam, data, scratch, shown):
    dataset = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    lines = ["## Hybrid belief on MRCLAM with a map prior (issue 12)", ""]
    if not os.path.exists(dataset):
        return lines + ["dataset absent", ""]
    lines += [__doc__.split("\n\n", 1)[1].replace("\n", " ").strip(), ""]
    jobs = []
    for robot in ROBOTS:
        log = os.path.join(scratch, f"mrclam-map-{robot}.jsonl")
        convert = [semslam, "convert", "mrclam", dataset, "--robot", str(robot), "--out", log] + CONVERT
        run_checked(convert)
        with open(log) as f:
            steps = sum(1 for _ in f) - 1  # the header, then a line per step
        if robot == 1:
            lines += ["```sh", shown(convert).replace(log, "mrclam-map-R.jsonl").replace("--robot 1", "--robot R")]
            for method, flags in METHODS:
                lines.append(shown([semslam, "run", "--method", method, "--in", log, "--out", "DIR",
                                    "--no-covariances", "--quiet", "--overwrite"] + flags).replace(
                                        log, "mrclam-map-R.jsonl"))
            lines += ["```", ""]
        for method, flags in METHODS:
            jobs.append((robot, method, log, steps, flags, os.path.join(scratch, f"mrclam-map-{robot}-{method}")))
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda job: _run(semslam, job[2], job[3], job[1], job[4], job[5]), jobs))
    lines += ["| robot | method | ATE rmse [m] | da_accuracy_real | pairwise precision | pairwise recall | "
              "components max/mean | time per step [ms] |", "|---|---|---|---|---|---|---|---|"]
    for (robot, method, *_), r in zip(jobs, results):
        lines.append(f"| {robot} | {method} | {r['ate']:.3f} | {r['da_real']:.3f} | {r['precision']:.3f} | "
                     f"{r['recall']:.3f} | {r['components']} | {r['time_per_step_ms']:.1f} |")
    lines.append("")
    for method, _ in METHODS:
        chosen = [r for (robot, m, *_), r in zip(jobs, results) if m == method]
        lines.append(f"- {method}: mean over robots ATE {sum(r['ate'] for r in chosen) / len(chosen):.3f} m, "
                     f"da_accuracy_real {sum(r['da_real'] for r in chosen) / len(chosen):.3f}.")
    return lines + [""]
