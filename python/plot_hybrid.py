#!/usr/bin/env python3
"""Paper A's figures for the hybrid belief, and the statistics of its study.

  plot_hybrid.py fig4 CLASSIFIER_RUN GEOMETRIC_RUN [--steps 1,3,5,9] [--out docs/figures/hybrid_fig4.png]
      The analog of paper A's Fig. 4: the mixture posterior over the current robot pose (eq. 6) at chosen steps,
      without (top row) and with (middle row) the classifier model: component means with their heading, 2-sigma
      position ellipses with line width by weight, ground truth; bottom row: P(beta_1:k | H_k) (eq. 8) of each
      history, blue without, red with, the true history circled green. The run folders are those of
      `semslam run --method hybrid|hybrid-geometric` on the same log.
  plot_hybrid.py fig5 STUDY_DIR [--out docs/figures/hybrid_fig5.png]
      The analog of Fig. 5: the four metrics at the final step against alpha, mean over layouts and tracks with the
      stratified bootstrap 95 % interval of the mean (det Sigma: geometric mean, on a log axis).
  plot_hybrid.py analyze STUDY_DIR [--alpha 0.25]
      Paired differences (classifier - geometric) per layout and pooled: stratified paired bootstrap 95 % interval,
      one-sided Wilcoxon signed-rank p-value, on how many layouts each metric separates (python/paired_statistics.py);
      the paired slope of the entropy against alpha; the NEES subsets of nees.csv; the disambiguation fractions.
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hypotheses  # noqa: E402  (python/hypotheses.py, beside this file)
import paired_statistics  # noqa: E402  (python/paired_statistics.py, beside this file)


def _read_numeric_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in r:
            if key not in ("model", "subset", "name"):
                r[key] = float(r[key])
    return rows


def read_runs(study):
    """runs.csv: the results of every run (the same bytes for any threads and ranks). A folder written before
    layouts existed has one layout, 0."""
    rows = _read_numeric_csv(os.path.join(study, "runs.csv"))
    for r in rows:
        r["layout"] = int(r.get("layout", 0))
        r["track"] = int(r["track"])
    return rows


def runs_of(rows):
    """The rows of runs.csv one per run: a track's geometric row appears at every alpha but is one run (the
    geometric model reads no class score: src/semslam/study/HybridStudy.h); its first appearance is kept."""
    seen, runs = set(), []
    for r in rows:
        if r["model"] == "geometric":
            key = (r["layout"], r["track"])
            if key in seen:
                continue
            seen.add(key)
        runs.append(r)
    return runs


def read_timings(study):
    """timings.csv: every run's sampling_s and time_s, and the layout (rank, threads, ranks, wall_time_s), one row
    per run (a track's geometric run serves every alpha of runs.csv: src/semslam/study/HybridStudy.h). A folder
    written before timings.csv existed kept the times in runs.csv."""
    path = os.path.join(study, "timings.csv")
    return _read_numeric_csv(path if os.path.exists(path) else os.path.join(study, "runs.csv"))


def read_nees(study):
    """nees.csv: {(alpha, model, subset): {mean, count, lower, upper, inside}}; a folder without subsets has
    the one subset "heaviest"."""
    result = {}
    for r in _read_numeric_csv(os.path.join(study, "nees.csv")):
        key = (r["alpha"], r["model"], r.get("subset", "heaviest"))
        result[key] = {"mean": r["nees_mean"], "count": int(r["count"]), "lower": r["lower"], "upper": r["upper"],
                       "inside": bool(r["lower"] <= r["nees_mean"] <= r["upper"])}
    return result


METRICS = [("entropy", "H(w) over P(beta)"), ("det_cov", "det(Sigma) of position"),
           ("err_wmax", "error of w_max [m]"), ("err_wavg", "weighted error [m]")]
NEES_SUBSETS = ("heaviest", "heaviest_correct", "heaviest_wrong", "mixture")


def mean_interval(groups, seed=1):
    """Mean of the values of `groups` (a list of per-layout lists) with its stratified bootstrap 95 % interval."""
    return paired_statistics.paired_bootstrap(groups, seed=seed)


def analyze(study, alpha=0.25):
    """Paper A's four metrics at `alpha` (the nearest in the study), classifier − geometric per track, compared per
    layout and pooled (python/paired_statistics.py: stratified paired bootstrap and one-sided Wilcoxon)."""
    rows = read_runs(study)
    alphas = sorted({r["alpha"] for r in rows})
    near = min(alphas, key=lambda a: abs(a - alpha))
    by = {(r["layout"], r["alpha"], r["model"], r["track"]): r for r in rows}
    layouts = sorted({r["layout"] for r in rows})
    pairs = sorted({(r["layout"], r["track"]) for r in rows if r["alpha"] == near})
    pairs = [p for p in pairs if (p[0], near, "classifier", p[1]) in by and (p[0], near, "geometric", p[1]) in by]
    result = {"alpha": near, "layouts": len(layouts), "tracks": len(pairs), "paired": {}, "nees": {},
              "disambiguated": {}}
    for metric, _ in METRICS:
        groups = {}
        for layout, track in pairs:
            c, g = by[(layout, near, "classifier", track)], by[(layout, near, "geometric", track)]
            if math.isfinite(c[metric]) and math.isfinite(g[metric]):
                groups.setdefault(layout, []).append(c[metric] - g[metric])
        comparison = paired_statistics.compare(groups)
        pooled = comparison["pooled"]
        means = {model: mean_interval([[by[(l, near, model, t)][metric] for (l, t) in pairs if l == layout]
                                       for layout in layouts])["mean"] for model in ("classifier", "geometric")}
        result["paired"][metric] = {"mean_difference": pooled["mean"], "ci_low": pooled["ci_low"],
                                    "ci_high": pooled["ci_high"], "p_less": pooled["p_less"],
                                    "nonzero": pooled["nonzero"], "median_difference": pooled["median"],
                                    "excludes_zero": pooled["separates"],
                                    "layouts_separating": comparison["layouts_separating"],
                                    "per_layout": comparison["layouts"],
                                    "classifier_mean": means["classifier"], "geometric_mean": means["geometric"]}
    if len(alphas) >= 2:
        slopes = {}
        for layout, track in sorted({(r["layout"], r["track"]) for r in rows}):
            xs = [a for a in alphas if (layout, a, "classifier", track) in by]
            ys = [by[(layout, a, "classifier", track)]["entropy"] for a in xs]
            if len(xs) < 2 or not all(math.isfinite(y) for y in ys):
                continue
            mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
            sxx = sum((x - mx) ** 2 for x in xs)
            slopes.setdefault(layout, []).append(sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx)
        e = mean_interval([slopes[layout] for layout in sorted(slopes)])
        result["entropy_slope"] = {"mean": e["mean"], "ci_low": e["ci_low"], "ci_high": e["ci_high"],
                                   "below_zero": bool(e["ci_high"] < 0)}
    nees = read_nees(study)
    for model in ("classifier", "geometric"):
        result["nees"][model] = {subset: nees[(near, model, subset)] for subset in NEES_SUBSETS
                                 if (near, model, subset) in nees}
        chosen = [by[(l, near, model, t)] for (l, t) in pairs]
        flags = [r["disambiguated_at_step"] for r in chosen]
        correct = [r["heaviest_history_correct"] for r in chosen]
        per_layout = {layout: sum(r["heaviest_history_correct"] for r in chosen if r["layout"] == layout) /
                      max(1, sum(1 for r in chosen if r["layout"] == layout)) for layout in layouts}
        result["disambiguated"][model] = {"fraction": sum(flags) / len(flags) if flags else float("nan"),
                                          "heaviest_correct": sum(correct) / len(correct) if correct else float("nan"),
                                          "heaviest_correct_per_layout": per_layout}
    # Per run, not per row: runs.csv repeats a track's one geometric run at every alpha (HybridStudy.h), and
    # timings.csv, summed below, has it once.
    runs = runs_of(rows)
    tv = [r["analytic_total_variation"] for r in runs if r["sampled_candidates"] > 0]
    result["sampled_vs_analytic_total_variation"] = sum(tv) / len(tv) if tv else float("nan")
    result["gate_lost_mass_max"] = max(r["gate_lost_mass"] for r in runs)
    timings = read_timings(study)
    result["sampled_candidates"] = sum(r["sampled_candidates"] for r in runs)
    result["sampling_s"] = sum(r["sampling_s"] for r in timings)
    result["run_s_total"] = sum(r["time_s"] for r in timings)
    return result


def fig5(study, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_runs(study)
    alphas = sorted({r["alpha"] for r in rows})
    layouts = sorted({r["layout"] for r in rows})
    tracks = len({(r["layout"], r["track"]) for r in rows})
    fig, axes = plt.subplots(1, 4, figsize=(16, 3.8))
    for ax, (metric, title) in zip(axes, METRICS):
        for model, color in (("geometric", "tab:blue"), ("classifier", "tab:red")):
            # det Sigma spans orders of magnitude (a track that never sees an object keeps the 10 m prior), so its
            # panel shows the geometric mean: the interval of the mean of log det Sigma, exponentiated.
            transform, back = (math.log, math.exp) if metric == "det_cov" else (float, float)
            stats = [mean_interval([[transform(r[metric]) for r in rows if r["alpha"] == a and r["model"] == model
                                     and r["layout"] == layout and math.isfinite(r[metric])] for layout in layouts])
                     for a in alphas]
            stats = [{key: back(s[key]) for key in ("mean", "ci_low", "ci_high")} for s in stats]
            ms = [s["mean"] for s in stats]
            err = [[s["mean"] - s["ci_low"] for s in stats], [s["ci_high"] - s["mean"] for s in stats]]
            ax.errorbar(alphas, ms, yerr=err, color=color, marker="o", capsize=3,
                        label="with classifier model" if model == "classifier" else "geometric only")
        ax.set_xlabel("alpha (classifier viewpoint dependency, A eq. 18)")
        ax.set_title(title + (" (geometric mean)" if metric == "det_cov" else ""))
        if metric == "det_cov":
            ax.set_yscale("log")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(f"Hybrid belief on aliased2d: final-step metrics against alpha ({len(layouts)} layouts, {tracks} "
                 "tracks; mean with stratified bootstrap 95 % interval)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def read_tum(path):
    poses = []
    if not os.path.exists(path):
        return poses
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                v = [float(x) for x in line.split()]
                poses.append((v[1], v[2]))
    return poses


def true_history(run):
    path = os.path.join(run, "associations.csv")
    history = {}
    if not os.path.exists(path):
        return history
    with open(path) as f:
        for r in csv.DictReader(f):
            history.setdefault(int(r["step"]), []).append(int(r["truth"]) if r["truth"] not in ("", "not-a-landmark") else -1)
    return history


def ellipse(ax, mean, heading, cov, width, color):
    import numpy as np
    c = math.cos(heading)
    s = math.sin(heading)
    R = np.array([[c, -s], [s, c]])
    world = R @ np.array(cov)[:2, :2] @ R.T
    vals, vecs = np.linalg.eigh(world)
    t = np.linspace(0, 2 * math.pi, 60)
    circle = np.stack([np.cos(t), np.sin(t)])
    pts = vecs @ (2.0 * np.sqrt(np.maximum(vals, 0))[:, None] * circle)
    ax.plot(mean[0] + pts[0], mean[1] + pts[1], color=color, linewidth=width)


def fig4(classifier, geometric, steps, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    runs = {"geometric": hypotheses.read(os.path.join(geometric, "hypotheses.jsonl")),
            "classifier": hypotheses.read(os.path.join(classifier, "hypotheses.jsonl"))}
    truth = read_tum(os.path.join(classifier, "truth.tum"))
    truth_hist = true_history(classifier)
    steps = [s for s in steps if s < len(runs["classifier"])]
    fig, axes = plt.subplots(3, len(steps), figsize=(4.2 * len(steps), 11), squeeze=False)
    for col, k in enumerate(steps):
        for row, (model, color) in enumerate((("geometric", "tab:blue"), ("classifier", "tab:red"))):
            ax = axes[row][col]
            if truth:
                ax.plot([p[0] for p in truth], [p[1] for p in truth], "g.-", linewidth=0.8, label="ground truth")
            record = runs[model][k]
            for comp in record["components"]:
                x, y, th = comp["pose"]
                w = comp["weight"]
                ellipse(ax, (x, y), th, comp["covariance"], 0.3 + 4.0 * w, color)
                ax.plot([x, x + 0.6 * math.cos(th)], [y, y + 0.6 * math.sin(th)], color="navy", linewidth=0.5 + 2 * w)
                ax.plot(x, y, "o", color=color, markersize=2 + 4 * w)
            ax.set_title(f"k = {k}, {'with' if model == 'classifier' else 'without'} classifier "
                         f"({len(record['components'])} comp.)", fontsize=9)
            ax.set_aspect("equal", adjustable="datalim")
            ax.set_xlabel("x [m]")
            ax.set_ylabel("y [m]")
            ax.grid(alpha=0.3)
            if col == 0:
                # Proxies: what the colours and marks stand for (sizes and widths grow with the weight).
                ax.plot([], [], "o", color=color, markersize=4, label="component mean (size: weight)")
                ax.plot([], [], color="navy", linewidth=1, label="heading")
                ax.plot([], [], color=color, linewidth=1, label="2-sigma position ellipse")
                ax.legend(fontsize=7, loc="best")
        ax = axes[2][col]
        histories = {}
        for model in ("geometric", "classifier"):
            for history, weight in hypotheses.association_marginal(runs[model], k):
                histories.setdefault(json.dumps(history), {})[model] = weight
        keys = sorted(histories, key=lambda h: -max(histories[h].values()))[:20]
        xs = range(len(keys))
        ax.bar([x - 0.2 for x in xs], [histories[h].get("geometric", 0) for h in keys], width=0.4, color="tab:blue",
               label="without classifier")
        ax.bar([x + 0.2 for x in xs], [histories[h].get("classifier", 0) for h in keys], width=0.4, color="tab:red",
               label="with classifier")
        true = [truth_hist.get(s, []) for s in range(k + 1)]
        for x, h in zip(xs, keys):
            if json.loads(h) == true:
                ax.plot(x, max(histories[h].values()) + 0.05, "o", markerfacecolor="none", markeredgecolor="green",
                        markersize=10)
        ax.set_ylim(0, 1.15)
        ax.set_title(f"P(beta_1:k | H_k), k = {k} (top 20)", fontsize=9)
        ax.set_xlabel("association history (rank by weight)")
        ax.set_ylabel("probability")
        ax.plot([], [], "o", markerfacecolor="none", markeredgecolor="green", label="true history")
        ax.set_xticks(list(xs))
        ax.set_xticklabels([str(i) for i in xs], fontsize=6)
        if col == 0:
            ax.legend(fontsize=8)
    fig.suptitle("Hybrid belief: posterior over the robot pose (eq. 6) and association marginal (eq. 8)")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p4 = sub.add_parser("fig4")
    p4.add_argument("classifier")
    p4.add_argument("geometric")
    p4.add_argument("--steps", default="1,3,5,9")
    p4.add_argument("--out", default=os.path.join("docs", "figures", "hybrid_fig4.png"))
    p5 = sub.add_parser("fig5")
    p5.add_argument("study")
    p5.add_argument("--out", default=os.path.join("docs", "figures", "hybrid_fig5.png"))
    pa = sub.add_parser("analyze")
    pa.add_argument("study")
    pa.add_argument("--alpha", type=float, default=0.25)
    args = parser.parse_args()
    if args.command == "fig4":
        fig4(args.classifier, args.geometric, [int(s) for s in args.steps.split(",")], args.out)
    elif args.command == "fig5":
        fig5(args.study, args.out)
    else:
        json.dump(analyze(args.study, args.alpha), sys.stdout, indent=2)
        print()


if __name__ == "__main__":
    main()
