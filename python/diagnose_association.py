#!/usr/bin/env python3
"""Where association went wrong in one run: reads a run folder's associations.csv (io/RunFolder.h) and prints

  1. every estimated landmark: its detections, the step of its first one, the true identities among them (a
     landmark holding two true ones is a merge; `C` is clutter), and the mean chi2 of its detections at the final
     estimate (rᵀR⁻¹r per detection, the `chi2` column: a static landmark seen consistently stays near the
     measurement dimension or below; something that moved, or detections of two objects, lie above);
  2. every true landmark: the estimates its detections ended on (more than one: a split; `null`: the null
     hypothesis or a dropped provisional landmark);
  3. the mean chi2 per detection over landmarks holding one true landmark only, and over landmarks holding clutter
     only: how far geometry alone separates static landmarks from clutter in this run;
  4. duplicates: for each true landmark, the estimates beyond its main one (the estimate holding most of its
     detections) on which it is the plurality identity, a second map of the same object, with the distance between
     the two at the final estimate (landmarks.csv) and whether a step had a detection on each (then the one-detection-
     per-landmark rule of docs/association-front-end.md §4 keeps them apart for good); a summary line counts them.

Usage: python3 python/diagnose_association.py RUN_DIR [RUN_DIR ...] [--min-detections N] [--duplicates-only]
(several run folders: each one's parts in turn, then part 4's summary over all of them)
Plain Python 3 (no plotting); docs/association-front-end.md §9 uses it.
"""
import argparse
import collections
import csv
import math
import os
import statistics
import sys

CLUTTER = "C"


def read_rows(run_dir):
    path = os.path.join(run_dir, "associations.csv")
    if not os.path.exists(path):
        sys.exit(f"diagnose_association.py: {path}: no such file (a run folder of `semslam run`)")
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        missing = {"step", "detection", "landmark", "truth", "chi2"} - set(reader.fieldnames or [])
        if missing:
            sys.exit(f"diagnose_association.py: {path}:1: missing columns {sorted(missing)}")
        rows = []
        for line, row in enumerate(reader, start=2):
            try:
                rows.append({
                    "step": int(row["step"]),
                    "landmark": row["landmark"],
                    "truth": CLUTTER if row["truth"] == "not-a-landmark" else row["truth"],
                    "chi2": float(row["chi2"]) if row["chi2"] else None,
                })
            except ValueError as error:
                sys.exit(f"diagnose_association.py: {path}:{line}: {error}")
    return rows


def read_positions(run_dir):
    """landmarks.csv's positions by id (x, y[, z]); {} where the file is absent."""
    path = os.path.join(run_dir, "landmarks.csv")
    if not os.path.exists(path):
        return {}
    positions = {}
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        for line, row in enumerate(reader, start=2):
            try:
                positions[row["id"]] = tuple(float(row[k]) for k in ("x", "y", "z") if row.get(k) not in (None, ""))
            except (KeyError, ValueError) as error:
                sys.exit(f"diagnose_association.py: {path}:{line}: {error}")
    return positions


def duplicates(rows, positions):
    """Part 4: (truth, main estimate, duplicate, its detections of truth, distance or None, seen at one step)."""
    plurality = {}
    held = collections.defaultdict(collections.Counter)
    steps = collections.defaultdict(set)
    for row in rows:
        if row["landmark"] != "null":
            held[row["landmark"]][row["truth"] or "?"] += 1
            steps[row["landmark"]].add(row["step"])
    for landmark, identities in held.items():
        plurality[landmark] = identities.most_common(1)[0][0]
    own = collections.defaultdict(collections.Counter)
    for row in rows:
        truth, landmark = row["truth"], row["landmark"]
        if truth and truth != CLUTTER and landmark != "null" and plurality[landmark] == truth:
            own[truth][landmark] += 1
    found = []
    for truth in sorted(own, key=lambda t: (len(t), t)):
        ranked = own[truth].most_common()
        main = ranked[0][0]
        for landmark, count in ranked[1:]:
            distance = (math.dist(positions[main], positions[landmark])
                        if main in positions and landmark in positions else None)
            found.append((truth, main, landmark, count, distance, bool(steps[main] & steps[landmark])))
    return found


def mean(values):
    return sum(values) / len(values) if values else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", nargs="+")
    parser.add_argument("--min-detections", type=int, default=3,
                        help="landmarks with fewer detections are left out of part 3 (default 3)")
    parser.add_argument("--duplicates-only", action="store_true", help="part 4 and its summary only")
    args = parser.parse_args()
    found = []
    for run_dir in args.run_dir:
        if len(args.run_dir) > 1:
            print(f"== {run_dir}")
        rows = read_rows(run_dir)
        if not args.duplicates_only:
            describe(rows, args.min_detections)
        run_found = duplicates(rows, read_positions(run_dir))
        print("4. duplicates (true landmark: main estimate, duplicate, its detections, distance at the estimate, "
              "seen at one step)")
        for truth, main, landmark, count, distance, shared in run_found:
            where = f"{distance:.2f} m" if distance is not None else "no position"
            print(f"  {truth:>5}  {main} <- {landmark}  {count:>4} det.  {where}{'  SEEN AT ONE STEP' if shared else ''}")
        found += run_found
    distances = [d for _, _, _, _, d, _ in found if d is not None]
    median = f"{statistics.median(distances):.2f} m" if distances else "n/a"
    print(f"duplicates: {len(found)} holding {sum(f[3] for f in found)} detections; median distance {median}; "
          f"{sum(1 for f in found if f[5])} holding {sum(f[3] for f in found if f[5])} detections seen at one step "
          f"with their main estimate")


def describe(rows, min_detections):
    """Parts 1-3 of one run."""
    by_estimate = collections.defaultdict(list)
    by_truth = collections.defaultdict(collections.Counter)
    for row in rows:
        if row["truth"]:
            by_truth[row["truth"]][row["landmark"]] += 1
        if row["landmark"] != "null":
            by_estimate[row["landmark"]].append(row)

    print("1. estimated landmarks (first step, detections, true identities, mean chi2 per detection)")
    for landmark in sorted(by_estimate, key=lambda j: (by_estimate[j][0]["step"], int(j))):
        held = by_estimate[landmark]
        identities = collections.Counter(r["truth"] or "?" for r in held).most_common()
        chi2 = [r["chi2"] for r in held if r["chi2"] is not None]
        flag = " MERGED" if len([t for t, _ in identities if t not in (CLUTTER, "?")]) > 1 else ""
        print(f"  {landmark:>5}  step {held[0]['step']:>6}  {len(held):>4} det.  "
              f"{' '.join(f'{t}:{n}' for t, n in identities)}  chi2 {mean(chi2):.2f}{flag}")

    print("2. true landmarks (detections, the estimates they ended on)")
    for truth in sorted((t for t in by_truth if t != CLUTTER), key=lambda t: (len(t), t)):
        on = by_truth[truth]
        flag = " SPLIT" if len([j for j in on if j != "null"]) > 1 else ""
        print(f"  {truth:>5}  {sum(on.values()):>4} det.  {' '.join(f'{j}:{n}' for j, n in on.most_common())}{flag}")
    if CLUTTER in by_truth:
        on = by_truth[CLUTTER]
        print(f"  clutter {sum(on.values())} det., {on['null']} on no landmark")

    print(f"3. mean chi2 per detection, landmarks of at least {min_detections} detections")
    pure_real, pure_clutter = [], []
    for held in by_estimate.values():
        identities = {r["truth"] for r in held}
        chi2 = [r["chi2"] for r in held if r["chi2"] is not None]
        if len(held) < min_detections or not chi2 or len(identities) != 1:
            continue
        (pure_clutter if identities == {CLUTTER} else pure_real).append(mean(chi2))
    for name, values in (("one true landmark", pure_real), ("clutter only", pure_clutter)):
        if values:
            print(f"  {name}: {len(values)} landmarks, chi2 per detection min {min(values):.2f} "
                  f"median {sorted(values)[len(values) // 2]:.2f} max {max(values):.2f}")
        else:
            print(f"  {name}: none")


if __name__ == "__main__":
    main()
