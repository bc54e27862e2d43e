"""docs/results.md section of issue 10's association ceiling under pose errors (docs/association-front-end.md §8);
used by make_results.py.

mm-nh's front end on MRCLAM Dataset 6 (robots 1-5, 3 classes, 10 % misclassification, label seed 1: the logs of the
association section) with its poses pinned to the known-DA estimate moved by s times their uncertainty
(`--on-known-trajectory --pose-error-scale s --pose-error-draw D --seed S`): the joint draw (the whole trajectory
from the known-DA posterior) at s = 0.5, 1, 2 and the independent one (each pose from its own marginal) at s = 0.5
and 1, seeds 1-3 each; s = 0 is the ceiling of the association section. Every cell is the mean `da_accuracy_real`
over the seeds with its range.

Beside it, decisions on the true history (docs/association-front-end.md §8b): mm-nh's front end deciding each detection on the
true history (`--on-true-history`: the graph holds the true associations, the decisions are scored, not applied),
label seeds 1-3 of each robot, against mm-nh's own run on the same logs: `decision_accuracy_real` and
`da_accuracy_real`, mean over the label seeds with the range, and the wrong decisions by kind summed over the seeds.
"""
import concurrent.futures
import csv
import os
import statistics
import sys

from results_commands import read_metrics, run_checked

HERE = os.path.dirname(os.path.abspath(__file__))
ROBOTS = [1, 2, 3, 4, 5]
SEEDS = [1, 2, 3]
# (draw, scale) columns after the unmoved ceiling
COLUMNS = [("joint", 0.5), ("joint", 1.0), ("joint", 2.0), ("independent", 0.5), ("independent", 1.0)]
CONVERT_ARGS = ["--keyframe-period", "1", "--classes", "3", "--misclassification", "0.1"]


def spread_cell(values):
    """Mean of the seeds' figures with their range, `–` when there are none."""
    if not values:
        return "–"
    if len(values) == 1:
        return f"{values[0]:.3f}"
    return f"{statistics.fmean(values):.3f} ({min(values):.3f}-{max(values):.3f})"


def ceiling_table(results):
    """Table lines from results[(robot, draw, scale, seed)] = da_accuracy_real, draw None and scale 0 for the
    unmoved ceiling; a mean row over the robots (of the per-robot means) closes it."""
    header = ["| robot | unmoved (s = 0) | " + " | ".join(f"{draw}, s = {scale:g}" for draw, scale in COLUMNS) + " |",
              "|---|---|" + "---|" * len(COLUMNS)]
    rows, column_means = [], [[] for _ in range(len(COLUMNS) + 1)]
    for robot in ROBOTS:
        unmoved = [v for (r, d, s, _), v in results.items() if r == robot and d is None]
        cells = [spread_cell(unmoved)]
        if unmoved:
            column_means[0].append(statistics.fmean(unmoved))
        for c, (draw, scale) in enumerate(COLUMNS):
            values = [results[(robot, draw, scale, seed)] for seed in SEEDS if (robot, draw, scale, seed) in results]
            cells.append(spread_cell(values))
            if values:
                column_means[c + 1].append(statistics.fmean(values))
        rows.append(f"| {robot} | " + " | ".join(cells) + " |")
    mean_row = "| mean | " + " | ".join(f"{statistics.fmean(m):.3f}" if m else "–" for m in column_means) + " |"
    return header + rows + [mean_row]


LABEL_SEEDS = [1, 2, 3]
DECISION_ERRORS = [("decisions_resighting_elsewhere", "re-sighting on another landmark"),
                   ("decisions_resighting_unassigned", "re-sighting unassigned"),
                   ("decisions_first_sighting_forced", "first sighting on a mapped landmark")]


def true_history_table(decided, own):
    """Table lines from decided[(robot, label_seed)] = the true-history run's metrics and own[(robot, label_seed)] =
    mm-nh's own da_accuracy_real; a mean row over the robots (of the per-robot means) closes it."""
    header = ["| robot | decisions on the true history: `decision_accuracy_real` | mm-nh's own `da_accuracy_real` | " +
              " | ".join(label for _, label in DECISION_ERRORS) + " | clutter rejected at decision |",
              "|---|---|---|" + "---|" * len(DECISION_ERRORS) + "---|"]
    rows, means = [], ([], [], [])
    for robot in ROBOTS:
        runs = [decided[(robot, seed)] for seed in LABEL_SEEDS if (robot, seed) in decided]
        accuracy = [m["decision_accuracy_real"] for m in runs]
        mine = [own[(robot, seed)] for seed in LABEL_SEEDS if (robot, seed) in own]
        clutter = [m["decision_clutter_rejected"] for m in runs if m["decision_clutter_rejected"] is not None]
        errors = [str(sum(m[key] for m in runs)) if runs else "–" for key, _ in DECISION_ERRORS]
        for target, values in zip(means, (accuracy, mine, clutter)):
            if values:
                target.append(statistics.fmean(values))
        rows.append(f"| {robot} | {spread_cell(accuracy)} | {spread_cell(mine)} | " + " | ".join(errors) +
                    f" | {spread_cell(clutter)} |")
    mean = [f"{statistics.fmean(m):.3f}" if m else "–" for m in means]
    mean_row = f"| mean | {mean[0]} | {mean[1]} | " + " | ".join("" for _ in DECISION_ERRORS) + f" | {mean[2]} |"
    return header + rows + [mean_row]


def write_csv(results, path):
    """results[(robot, draw, scale, seed)] as the CSV that plot_association_ceiling.py reads."""
    def order(item):  # robot, then the unmoved ceiling (draw None) first, scale, seed
        robot, draw, scale, seed = item[0]
        return robot, draw or "", scale, seed

    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["robot", "draw", "scale", "seed", "da_accuracy_real"])
        for (robot, draw, scale, seed), value in sorted(results.items(), key=order):
            writer.writerow([robot, draw or "", f"{scale:g}", seed, repr(value)])


def association_ceiling_section(semslam, data, scratch, shown, python=None):
    folder = os.path.join(data, "mrclam", "MRCLAM_Dataset6")
    lines = ["## The association ceiling under pose errors (issue 10)", ""]
    if not os.path.isdir(folder):
        return lines + [f"MRCLAM Dataset 6 is not at {folder}: section skipped.", ""]
    lines += ["mm-nh's front end with the poses pinned to the known-DA estimate, moved by s times its uncertainty "
              "(docs/association-front-end.md §8): `joint`, the whole trajectory drawn from the known-DA posterior "
              "(consecutive poses err together, as an estimate's do); `independent`, each pose from its own "
              "marginal (consecutive poses err independently). `da_accuracy_real`, mean over seeds 1-3 with the "
              "range; MRCLAM Dataset 6, whole recordings at 1 s keyframes, 3 classes, 10 % misclassification, "
              "label seed 1. The known-DA trajectory was fitted with every detection on its true landmark, so its "
              "poses carry part of the truth to the decisions judged from them: about 4 points of these figures "
              "(docs/association-front-end.md §8, §8b; the next table is the front end's own figure).", ""]
    logs = {robot: os.path.join(scratch, f"association_ceiling_r{robot}.jsonl") for robot in ROBOTS}
    tasks = []
    for robot in ROBOTS:
        tasks.append((robot, None, 0.0, 1))
        for draw, scale in COLUMNS:
            tasks += [(robot, draw, scale, seed) for seed in SEEDS]

    def command(task):
        robot, draw, scale, seed = task
        out = os.path.join(scratch, f"association_ceiling_r{robot}_{draw}_{scale:g}_{seed}")
        extra = [] if draw is None else ["--pose-error-scale", f"{scale:g}", "--pose-error-draw", draw,
                                         "--seed", str(seed)]
        return out, [semslam, "run", "--overwrite", "--method", "mm-nh", "--in", logs[robot], "--out", out,
                     "--no-covariances", "--quiet", "--on-known-trajectory"] + extra

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, (os.cpu_count() or 2))) as pool:
        list(pool.map(lambda robot: run_checked([semslam, "convert", "mrclam", folder, "--out", logs[robot],
                                                 "--robot", str(robot)] + CONVERT_ARGS), ROBOTS))
        list(pool.map(lambda task: run_checked(command(task)[1]), tasks))
    results = {task: read_metrics(command(task)[0])["da_accuracy_real"] for task in tasks}
    lines += ceiling_table(results) + [""]
    table = os.path.join(scratch, "association_ceiling.csv")
    write_csv(results, table)
    figures = os.path.join("docs", "figures")
    os.makedirs(figures, exist_ok=True)
    figure = os.path.join(figures, "association_ceiling.png")
    run_checked([python or sys.executable, os.path.join(HERE, "plot_association_ceiling.py"), table, figure])
    lines += [f"![association ceiling under pose errors]({os.path.relpath(figure, 'docs')})", "",
              "`python3 python/plot_association_ceiling.py CEILING.csv OUT.png` (columns robot, draw, scale, seed, "
              "da_accuracy_real).", ""]
    lines += ["```sh",
              shown([semslam, "convert", "mrclam", folder, "--out", "rN.jsonl", "--robot", "N"] + CONVERT_ARGS),
              "build/bin/semslam run --method mm-nh --in rN.jsonl --out DIR --no-covariances --on-known-trajectory "
              "--pose-error-scale S --pose-error-draw joint|independent --seed SEED",
              "```", ""]
    return lines + true_history_lines(semslam, folder, scratch, shown, logs)


def true_history_lines(semslam, folder, scratch, shown, seed_one_logs):
    """The second table: every robot and label seed deciding on the true history and on its own decisions.
    seed_one_logs[robot]: the first table's logs, label seed 1 (converted once, not again)."""
    lines = ["### Decisions on the true history", "",
             "mm-nh's front end deciding each detection with every earlier association right (`--on-true-history`: "
             "the graph holds the true associations; each decision is scored, never applied; docs/"
             "association-front-end.md §8b), against mm-nh deciding for itself on the same logs. Mean over label "
             "seeds 1-3 with the range; wrong decisions by kind summed over the seeds; MRCLAM Dataset 6, whole "
             "recordings at 1 s keyframes, 3 classes, 10 % misclassification.", ""]
    logs = {(robot, seed): seed_one_logs[robot] if seed == 1 else
            os.path.join(scratch, f"true_history_r{robot}_s{seed}.jsonl") for robot in ROBOTS for seed in LABEL_SEEDS}
    out = {(kind, robot, seed): os.path.join(scratch, f"true_history_{kind}_r{robot}_s{seed}")
           for kind in ("decided", "own") for robot in ROBOTS for seed in LABEL_SEEDS}

    def run(task):
        kind, robot, seed = task
        extra = ["--on-true-history"] if kind == "decided" else []
        run_checked([semslam, "run", "--overwrite", "--method", "mm-nh", "--in", logs[(robot, seed)], "--out",
                     out[task], "--no-covariances", "--quiet"] + extra)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, (os.cpu_count() or 2))) as pool:
        list(pool.map(lambda key: run_checked([semslam, "convert", "mrclam", folder, "--out", logs[key], "--robot",
                                               str(key[0]), "--seed", str(key[1])] + CONVERT_ARGS),
                      [key for key in logs if key[1] != 1]))
        list(pool.map(run, sorted(out, key=lambda task: task[0] == "decided")))  # the slower own runs first
    decided = {(r, s): read_metrics(out[("decided", r, s)]) for r in ROBOTS for s in LABEL_SEEDS}
    own = {(r, s): read_metrics(out[("own", r, s)])["da_accuracy_real"] for r in ROBOTS for s in LABEL_SEEDS}
    lines += true_history_table(decided, own) + [""]
    lines += ["```sh",
              shown([semslam, "convert", "mrclam", folder, "--out", "rN-S.jsonl", "--robot", "N", "--seed", "S"] +
                    CONVERT_ARGS),
              "build/bin/semslam run --method mm-nh --in rN-S.jsonl --out DIR --no-covariances --on-true-history",
              "build/bin/semslam run --method mm-nh --in rN-S.jsonl --out DIR --no-covariances",
              "```", ""]
    return lines
