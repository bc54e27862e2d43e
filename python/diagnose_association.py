#!/usr/bin/env python3
"""Where association went wrong in one run: reads a run folder's associations.csv (io/RunFolder.h) and prints

  1. every estimated landmark: its detections, the step of its first one, the true identities among them (a
     landmark holding two true ones is a merge; `C` is clutter), and the mean chi2 of its detections at the final
     estimate (rᵀR⁻¹r per detection, the `chi2` column: a static landmark seen consistently stays near the
     measurement dimension or below; something that moved, or detections of two objects, lie above);
  2. every true landmark: the estimates its detections ended on (more than one: a split; `null`: the null
     hypothesis or a dropped provisional landmark);
  3. the mean chi2 per detection over landmarks holding one true landmark only, and over landmarks holding clutter
     only: how far geometry alone separates static landmarks from clutter in this run.

Usage: python3 python/diagnose_association.py RUN_DIR [--min-detections N]
Plain Python 3 (no plotting); docs/association-front-end.md §9 uses it.
"""
import argparse
import collections
import csv
import os
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


def mean(values):
    return sum(values) / len(values) if values else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir")
    parser.add_argument("--min-detections", type=int, default=3,
                        help="landmarks with fewer detections are left out of part 3 (default 3)")
    args = parser.parse_args()
    rows = read_rows(args.run_dir)

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

    print(f"3. mean chi2 per detection, landmarks of at least {args.min_detections} detections")
    pure_real, pure_clutter = [], []
    for held in by_estimate.values():
        identities = {r["truth"] for r in held}
        chi2 = [r["chi2"] for r in held if r["chi2"] is not None]
        if len(held) < args.min_detections or not chi2 or len(identities) != 1:
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
