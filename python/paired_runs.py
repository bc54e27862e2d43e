"""Paired comparison of two settings run on the same logs: each run folder of CANDIDATE against the folder of the same
name under BASELINE, metric by metric (metrics.json). Prints, per metric, the runs compared (both values defined),
the mean difference candidate − baseline with its paired bootstrap interval (python/paired_statistics.py), the
standard deviation of the differences, the paired t statistic, and on how many runs the candidate is higher and
lower. Used for the one-off comparisons of docs/association-front-end.md (e.g. §6, `--switch-rounds 5` against the
default over MRCLAM's 15 runs). First it says what the two settings are: the entries of the runs' settings.json
(docs/max-mixtures.md, "What a run reports") in which the paired folders differ, and on how many pairs.

Usage: paired_runs.py BASELINE_ROOT CANDIDATE_ROOT [--metric NAME ...] [--prefix P ...]
"""
import argparse
import json
import math
import os
import sys

import paired_statistics

DEFAULT_METRICS = ["da_accuracy_real", "ate_rmse", "clutter_rejected_moving"]


def differences(baseline_root, candidate_root, metric, prefixes=None):
    """{run name: candidate − baseline} over the folders present under both roots whose names start with one of
    `prefixes` (all when None) and whose metric is defined in both."""
    result = {}
    for name in sorted(os.listdir(candidate_root)):
        if prefixes and not any(name.startswith(p) for p in prefixes):
            continue
        paths = [os.path.join(root, name, "metrics.json") for root in (baseline_root, candidate_root)]
        if not all(os.path.isfile(p) for p in paths):
            continue
        base, cand = (json.load(open(p)).get(metric) for p in paths)
        if base is None or cand is None:
            continue
        result[name] = cand - base
    return result


def flattened(settings, prefix=""):
    """{"association.gate": 0.999999, ...}: a settings.json's entries by their dotted paths (schema and release
    left out: they say which build wrote the folder, not how it ran)."""
    entries = {}
    for key, value in settings.items():
        if not prefix and key in ("schema", "version"):
            continue
        if isinstance(value, dict):
            entries.update(flattened(value, prefix + key + "."))
        else:
            entries[prefix + key] = value
    return entries


def setting_differences(baseline_root, candidate_root, prefixes=None):
    """{(entry, baseline value, candidate value): pairs} over the paired folders that both hold a settings.json
    (values as JSON text; a missing entry as None), the number of those pairs, and of the pairs without one on
    either side."""
    found, recorded, unrecorded = {}, 0, 0
    for name in sorted(os.listdir(candidate_root)):
        if prefixes and not any(name.startswith(p) for p in prefixes):
            continue
        folders = [os.path.join(root, name) for root in (baseline_root, candidate_root)]
        if not all(os.path.isfile(os.path.join(f, "metrics.json")) for f in folders):
            continue
        paths = [os.path.join(f, "settings.json") for f in folders]
        if not all(os.path.isfile(p) for p in paths):
            unrecorded += 1
            continue
        recorded += 1
        base, cand = (flattened(json.load(open(p))) for p in paths)
        for entry in sorted(set(base) | set(cand)):
            if base.get(entry, None) != cand.get(entry, None) or (entry in base) != (entry in cand):
                key = (entry, json.dumps(base[entry]) if entry in base else None,
                       json.dumps(cand[entry]) if entry in cand else None)
                found[key] = found.get(key, 0) + 1
    return found, recorded, unrecorded


def summary(values):
    """Count, mean, its bootstrap interval, standard deviation, paired t, higher and lower counts."""
    n = len(values)
    if n == 0:
        return {"count": 0}
    mean = sum(values) / n
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1)) if n > 1 else float("nan")
    t = mean / (sd / math.sqrt(n)) if n > 1 and sd > 0 else float("nan")
    interval = paired_statistics.paired_bootstrap([values])
    return {"count": n, "mean": mean, "ci_low": interval["ci_low"], "ci_high": interval["ci_high"], "sd": sd,
            "t": t, "higher": sum(v > 0 for v in values), "lower": sum(v < 0 for v in values)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("baseline")
    parser.add_argument("candidate")
    parser.add_argument("--metric", action="append")
    parser.add_argument("--prefix", action="append")
    args = parser.parse_args(argv)
    differing, recorded, unrecorded = setting_differences(args.baseline, args.candidate, args.prefix)
    for (entry, base, cand), pairs in sorted(differing.items()):
        print(f"settings: {entry} {base if base is not None else '(absent)'} -> "
              f"{cand if cand is not None else '(absent)'} on {pairs} pairs")
    if recorded and not differing:
        print(f"settings: the same on all {recorded} pairs that record them")
    if unrecorded:
        print(f"settings: {unrecorded} pairs without a settings.json on one side (folders older than the file)")
    for metric in args.metric or DEFAULT_METRICS:
        s = summary(list(differences(args.baseline, args.candidate, metric, args.prefix).values()))
        if s["count"] == 0:
            print(f"{metric}: no run has it in both")
            continue
        print(f"{metric}: {s['count']} runs, mean difference {s['mean']:+.4f} (95 % bootstrap {s['ci_low']:+.4f} to "
              f"{s['ci_high']:+.4f}), sd {s['sd']:.4f}, t {s['t']:+.2f}, higher on {s['higher']}, lower on "
              f"{s['lower']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
