#!/usr/bin/env python3
"""Step time of the incremental smoother against step, on exploration without revisits (and on manhattan).

Usage: plot_incremental_steps.py [--build build] [--steps 3000] [--out docs/incremental-step-times.png]

1. Simulates a semantic run that never returns to a place: `semslam simulate semantic --path lawnmower` with rows
   200 m long, 40 m apart (landmarks lie at most 6 m beside the path and the sensor sees 10 m, so nothing seen
   from one row is seen from another, and no row is driven twice).
2. Writes it as an iSAM pose graph with the true data association: ODOMETRY from each odometry record, LANDMARK
   (the landmark's position in the robot frame) from each range-bearing detection, its covariance propagated to
   first order, J diag(σ_r², σ_b²) Jᵀ; clutter (truth −1) is left out. Square-root information R with RᵀR = Σ⁻¹.
3. Replays it with `semslam optimize FILE --format isam --incremental --step-times CSV`, and manhattan as well
   when the shared data is present, and plots each update's wall time against its step, with a running median.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MANHATTAN = os.path.join(ROOT, "..", "shared", "data", "vertigo", "manhattan", "originalDataset", "g2o",
                         "manhattanOlson3500.g2o")


def sqrt_information(covariance):
    """Upper-triangular R with RᵀR = Σ⁻¹ (R = Lᵀ for the Cholesky factor L Lᵀ of Σ⁻¹)."""
    return np.linalg.cholesky(np.linalg.inv(np.asarray(covariance))).T


def upper(matrix):
    n = matrix.shape[0]
    return [matrix[i, j] for i in range(n) for j in range(i, n)]


def log_to_isam(log_path, isam_path):
    with open(log_path) as f:
        header = json.loads(f.readline())
        records = [json.loads(line) for line in f if line.strip()]
    if header.get("dimension") != 2 or header["sensor"]["kind"] != "range-bearing":
        sys.exit("expected a 2D range-bearing log")
    sx, sy, st = header["sensor"].get("body_to_sensor", [0.0, 0.0, 0.0])
    lines = []
    first_observations = []  # the first pose's, written after the first odometry record (iSAM's rule)
    for i, record in enumerate(records):
        if i > 0:
            odometry = record["odometry"]
            R = sqrt_information(odometry["covariance"])
            lines.append("ODOMETRY %d %d %s %s" % (i - 1, i, " ".join("%.17g" % v for v in odometry["increment"]),
                                                    " ".join("%.17g" % v for v in upper(R))))
        for detection in record["detections"]:
            if detection.get("truth", -1) < 0:
                continue
            r, b = detection["geometry"]
            # The point in the sensor frame, then in the body frame.
            px, py = r * math.cos(b), r * math.sin(b)
            J = np.array([[math.cos(b), -r * math.sin(b)], [math.sin(b), r * math.cos(b)]])
            rotation = np.array([[math.cos(st), -math.sin(st)], [math.sin(st), math.cos(st)]])
            point = rotation @ np.array([px, py]) + np.array([sx, sy])
            covariance = rotation @ J @ np.asarray(detection["covariance"]) @ J.T @ rotation.T
            R = sqrt_information(covariance)
            line = "LANDMARK %d %d %.17g %.17g %s" % (i, detection["truth"], point[0], point[1],
                                                     " ".join("%.17g" % v for v in upper(R)))
            (first_observations if i == 0 else lines).append(line)
        if i == 1:
            lines.extend(first_observations)
    with open(isam_path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return len(records)


def replay(cli, graph, fmt, work, name):
    csv_path = os.path.join(work, name + "_steps.csv")
    report = os.path.join(work, name + "_report.json")
    subprocess.run([cli, "optimize", graph, "--format", fmt, "--incremental", "--step-times", csv_path,
                    "--report", report], check=True, stdout=subprocess.DEVNULL)
    with open(csv_path) as f:
        times = [float(row["seconds"]) for row in csv.DictReader(f)]
    with open(report) as f:
        return np.array(times), json.load(f)


def running_median(values, window):
    half = window // 2
    return np.array([np.median(values[max(0, i - half):i + half + 1]) for i in range(len(values))])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--steps", type=int, default=3000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "incremental-step-times.png"))
    args = parser.parse_args()
    cli = os.path.join(args.build, "bin", "semslam")
    work = os.path.join(args.build, "incremental-steps")
    os.makedirs(work, exist_ok=True)

    log_path = os.path.join(work, "exploration.jsonl")
    subprocess.run([cli, "simulate", "semantic", "--path", "lawnmower", "--row-length", "200", "--row-spacing",
                    "40", "--steps", str(args.steps), "--seed", str(args.seed), "--out", log_path], check=True,
                   stdout=subprocess.DEVNULL)
    isam_path = os.path.join(work, "exploration.isam.txt")
    log_to_isam(log_path, isam_path)
    runs = [("exploration without revisits (semantic simulator, lawnmower, %d steps)" % args.steps,
             *replay(cli, isam_path, "isam", work, "exploration"))]
    if os.path.exists(MANHATTAN):
        runs.append(("manhattan (loop closures throughout)", *replay(cli, MANHATTAN, "g2o", work, "manhattan")))

    fig, axes = plt.subplots(len(runs), 1, figsize=(9, 3.6 * len(runs)), squeeze=False)
    for axis, (title, times, report) in zip(axes[:, 0], runs):
        steps = np.arange(len(times))
        axis.plot(steps, 1e3 * times, ".", markersize=2, alpha=0.35, color="tab:blue", label="one update")
        axis.plot(steps, 1e3 * running_median(times, 101), color="tab:red", label="running median (101 steps)")
        axis.set_yscale("log")
        axis.set_xlabel("step (pose)")
        axis.set_ylabel("update + newest-pose read [ms]")
        axis.set_title("%s: replay %.2f s, worst step %.1f ms" % (title, report["replay_time_s"],
                                                                  1e3 * report["worst_step_time_s"]), fontsize=9)
        axis.legend(loc="upper left", fontsize=8)
        axis.grid(True, which="both", alpha=0.3)
        third = len(times) // 3
        print("%s: median step %.3f ms over the first third, %.3f ms over the last third" %
              (title, 1e3 * np.median(times[:third]), 1e3 * np.median(times[-third:])))
    fig.suptitle("IncrementalSmoother step time (relinearize threshold %g, wildfire %g)" %
                 (runs[0][2]["relinearize_threshold"], runs[0][2]["wildfire_threshold"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
