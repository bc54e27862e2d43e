#!/usr/bin/env python3
"""Draw the map of one run on a KITTI tracking log (issue 11; docs/results.md, section kitti-tracking), from above.

Usage: plot_kitti_tracking.py LOG.jsonl RUN_DIR --out FILE.png [--title TEXT]

LOG is the measurement log the run read (`semslam convert kitti-tracking`), RUN_DIR its run folder (`semslam run`;
files of src/semslam/io/RunFolder.h). Drawn in the log's world frame (x forward, y left at the first pose), z dropped:

  - the reference trajectory (the log's true_pose: ORB-SLAM3's, truth.tum) and the estimate (trajectory.tum);
  - the confirmed landmarks: the run's landmarks.csv (the estimates it kept);
  - the static tracks: landmarks_truth.csv (each landmark's mean world position through the reference);
  - the moving tracks: the detections whose truth is not-a-landmark with a clutter_source, one line per source
    (track), through the estimated pose of their step;
  - the rejected detections: those associations.csv puts on no landmark (`null`), other than moving tracks' ones,
    split into real ones (truth a landmark: a static car the run left out) and the rest (false positives, unknown);
  - clutter put on a landmark: not-a-landmark detections associations.csv puts on one (an error).

A detection's world position is R(q_k) p + t_k with (t_k, q_k) row k of trajectory.tum (one row per log step, in
step order) and p its geometry (relative-position, body axes). Needs matplotlib (Debian: python3-matplotlib).
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from log_geometry import world  # noqa: E402


def read_tum(path):
    """Rows (x, y, z, qx, qy, qz, qw) of a TUM file, in order."""
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("#") or not line.strip():
                continue
            fields = line.split()
            if len(fields) != 8:
                sys.exit(f"plot_kitti_tracking.py: {path}:{number}: expected 8 fields, found {len(fields)}")
            rows.append(tuple(float(v) for v in fields[1:]))
    return rows


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_log_detections(path):
    """Per step, the list of (geometry, truth, clutter_source) of its detections."""
    steps = []
    with open(path) as f:
        next(f)
        for line in f:
            record = json.loads(line)
            steps.append([(d["geometry"], d.get("truth"), d.get("clutter_source")) for d in record["detections"]])
    return steps


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("log")
    parser.add_argument("run_dir")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    estimate = read_tum(os.path.join(args.run_dir, "trajectory.tum"))
    reference_path = os.path.join(args.run_dir, "truth.tum")
    reference = read_tum(reference_path) if os.path.exists(reference_path) else []
    steps = read_log_detections(args.log)
    if len(steps) != len(estimate):
        sys.exit(f"plot_kitti_tracking.py: {args.log} has {len(steps)} steps but {args.run_dir}/trajectory.tum "
                 f"{len(estimate)} poses: not the log of this run")
    assigned = {}
    for row in read_csv(os.path.join(args.run_dir, "associations.csv")):
        assigned[(int(row["step"]), int(row["detection"]))] = row["landmark"] != "null"

    moving, rejected_real, rejected_other, clutter_on_landmark = {}, [], [], []
    for k, detections in enumerate(steps):
        for j, (geometry, truth, source) in enumerate(detections):
            p = world(estimate[k], geometry)
            if source is not None:
                moving.setdefault(source, []).append(p)
            elif not assigned.get((k, j), False):
                (rejected_real if isinstance(truth, int) else rejected_other).append(p)
            elif truth == "not-a-landmark":
                clutter_on_landmark.append(p)

    figure, axes = plt.subplots(figsize=(9, 8))
    if reference:
        axes.plot([r[0] for r in reference], [r[1] for r in reference], "--", color="0.55", lw=1.2,
                  label="reference trajectory (ORB-SLAM3)")
    axes.plot([e[0] for e in estimate], [e[1] for e in estimate], "-", color="tab:blue", lw=1.5,
              label="estimated trajectory")
    for i, points in enumerate(sorted(moving.items())):
        xs, ys = [p[0] for p in points[1]], [p[1] for p in points[1]]
        axes.plot(xs, ys, ".-", color="tab:orange", lw=1.0, ms=3, alpha=0.8,
                  label=f"moving tracks ({len(moving)}, one line each)" if i == 0 else None)
    if rejected_other:
        axes.scatter([p[0] for p in rejected_other], [p[1] for p in rejected_other], marker="x", s=12, color="0.5",
                     lw=0.7, label=f"rejected detections: false positive or unknown ({len(rejected_other)})")
    if rejected_real:
        axes.scatter([p[0] for p in rejected_real], [p[1] for p in rejected_real], marker="x", s=16, color="tab:red",
                     lw=0.9, label=f"rejected detections of static tracks ({len(rejected_real)})")
    if clutter_on_landmark:
        axes.scatter([p[0] for p in clutter_on_landmark], [p[1] for p in clutter_on_landmark], marker="+", s=30,
                     color="tab:purple", lw=1.0, label=f"clutter put on a landmark ({len(clutter_on_landmark)})")
    truth = read_csv(os.path.join(args.run_dir, "landmarks_truth.csv"))
    if truth:
        axes.scatter([float(t["x"]) for t in truth], [float(t["y"]) for t in truth], marker="o", s=70,
                     facecolors="none", edgecolors="black", lw=1.0, label=f"static tracks ({len(truth)})")
    landmarks = read_csv(os.path.join(args.run_dir, "landmarks.csv"))
    if landmarks:
        axes.scatter([float(l["x"]) for l in landmarks], [float(l["y"]) for l in landmarks], marker="s", s=22,
                     color="tab:green", label=f"confirmed landmarks ({len(landmarks)})", zorder=3)
    axes.set_xlabel("x [m] (forward at the first pose)")
    axes.set_ylabel("y [m] (left at the first pose)")
    axes.set_aspect("equal", adjustable="datalim")
    axes.grid(True, lw=0.3)
    axes.legend(loc="best", fontsize=8)
    if args.title:
        axes.set_title(args.title, fontsize=10)
    figure.tight_layout()
    figure.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
