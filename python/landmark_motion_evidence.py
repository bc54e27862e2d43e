#!/usr/bin/env python3
"""Is a landmark one static object? Per landmark of a finished run, the log evidence of a point that moves as a
random walk against a static point, each over the whole graph of the run's final associations
(docs/association-front-end.md §9, "The lead: a random walk chosen by its evidence").

The graph is the run's: the first pose's prior (the log's, or σ = 1e-6 at the run's first pose, as the run's gauge),
every odometry factor, and a range-bearing factor for every detection the run left on a mapped landmark
(associations.csv; detections on null are left out, as the run's estimate has them). The static model is that graph;
the random walk for landmark l gives each detection of l after its first a position of its own, joined to the
previous one by a random-walk prior N(0, q Δt I) (Δt the time between the two detections). Both are solved
(semslam.optimize, from the run's estimate) and compared by Laplace's approximation of their evidence
(semslam.laplace_evidence_score, solve/LaplaceEvidence.h; the positions' priors are proper Gaussians there, so the
extra positions pay for themselves only where the detections wander):

    Δ = ln p(Z | random walk) − ln p(Z | static) = −½ (score_random_walk − score_static).

Δ > 0 favours the random walk: something that moved (another robot), or detections of several objects. The run
must be of a 2D log with a range-bearing sensor at the body origin (MRCLAM, Lost in the Woods); a diagnostic, slow
on long logs (one whole-graph solve per landmark).

With `--write-without-flagged OUT`, the log is also written without the detections the run left on a landmark
whose Δ exceeds `--above` (default 5): what demoting those landmarks as they were made would give at best
(python/oracle_logs.py writes it; docs/results.md, section `association-oracles`, runs mm-nh on it).

Usage: PYTHONPATH=build/python python3 python/landmark_motion_evidence.py LOG RUN_DIR [--q 0.005]
           [--write-without-flagged OUT [--above 5]]
Needs the semslam Python module (built by `make build` into build/python).
"""
import argparse
import collections
import csv
import json
import math
import os
import sys

import numpy as np

import oracle_logs
import semslam

# A random walk's extra positions take keys above every landmark a run can have.
EXTRA_KEY_OFFSET = 10 ** 9


def read_run(log_path, run_dir):
    """(header, steps, poses N×3, {landmark id: position},
    [(step, landmark id, range, bearing, covariance, truth, detection index within its step)])."""
    with open(log_path) as f:
        header = json.loads(next(f))
        steps = [json.loads(line) for line in f]
    sensor = header["sensor"]
    if header.get("dimension") != 2 or sensor["kind"] != "range-bearing":
        raise ValueError(f"{log_path}: a 2D range-bearing log is needed, this one is "
                         f"{header.get('dimension')}D {sensor['kind']}")
    if any(abs(v) > 0 for v in sensor.get("body_to_sensor", [0.0, 0.0, 0.0])):
        raise ValueError(f"{log_path}: the sensor must sit at the body origin (body_to_sensor the identity)")
    poses = []
    with open(os.path.join(run_dir, "trajectory.tum")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            _, x, y, _, qx, qy, qz, qw = map(float, line.split())
            poses.append((x, y, math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))))
    if len(poses) != len(steps):
        raise ValueError(f"{run_dir}/trajectory.tum: {len(poses)} poses for the log's {len(steps)} steps")
    with open(os.path.join(run_dir, "landmarks.csv"), newline="") as f:
        landmarks = {int(r["id"]): np.array([float(r["x"]), float(r["y"])]) for r in csv.DictReader(f)}
    detections = []
    with open(os.path.join(run_dir, "associations.csv"), newline="") as f:
        for r in csv.DictReader(f):
            try:
                landmark = int(r["landmark"])
            except ValueError:  # "null": the null hypothesis, a dropped landmark, rejected
                continue
            if landmark not in landmarks:
                continue
            k = int(r["step"])
            d = steps[k]["detections"][int(r["detection"])]
            detections.append((k, landmark, d["geometry"][0], d["geometry"][1], d["covariance"], r["truth"],
                               int(r["detection"])))
    return header, steps, np.array(poses), landmarks, detections


def detections_on(detections, flagged):
    """{(step index, detection index)} of every detection of read_run's list that is on a landmark in `flagged`."""
    return {(d[0], d[6]) for d in detections if d[1] in flagged}


def motion_graph(header, steps, poses):
    """The run's pose prior and odometry factors: the part of the graph every model shares."""
    graph = semslam.FactorGraph()
    prior = header.get("initial_pose")
    if prior:
        graph.add(semslam.PriorFactorSE2(semslam.pose_key(0), semslam.SE2(*prior["mean"]),
                                         semslam.NoiseModel.from_covariance(np.array(prior["covariance"]))))
    else:
        graph.add(semslam.PriorFactorSE2(semslam.pose_key(0), semslam.SE2(*poses[0]),
                                         semslam.NoiseModel.isotropic(3, 1e-6)))
    for k in range(1, len(steps)):
        odometry = steps[k]["odometry"]
        graph.add(semslam.BetweenFactorSE2(semslam.pose_key(k - 1), semslam.pose_key(k),
                                           semslam.SE2(*odometry["increment"]),
                                           semslam.NoiseModel.from_covariance(np.array(odometry["covariance"]))))
    return graph


def detection_factor(detection, landmark_key):
    """The range-bearing factor of one detection of read_run's list on a key."""
    k, _, r, bearing, covariance = detection[:5]
    return semslam.RangeBearingFactor(semslam.pose_key(k), landmark_key, np.array([r, bearing]),
                                      semslam.NoiseModel.from_covariance(np.array(covariance)))


def static_graph(motion, detections, skip_landmark=None):
    """The run's graph (`motion` and every detection on its landmark), without the detections of `skip_landmark`."""
    graph = semslam.FactorGraph()
    graph.add_graph(motion)
    for detection in detections:
        if detection[1] != skip_landmark:
            graph.add(detection_factor(detection, semslam.landmark_key(detection[1])))
    return graph


def initial_values(poses, landmarks, detections):
    """The run's estimate of every pose and of every landmark some detection is on (the graph's variables)."""
    values = semslam.Values()
    for k, pose in enumerate(poses):
        values.insert(semslam.pose_key(k), semslam.SE2(*pose))
    for landmark in sorted({d[1] for d in detections}):
        values.insert(semslam.landmark_key(landmark), landmarks[landmark])
    return values


def random_walk_evidence(header, steps, poses, landmarks, detections, q):
    """{landmark id: Δ} for every landmark with at least 3 detections (Δ as in the module comment)."""
    motion = motion_graph(header, steps, poses)
    base = static_graph(motion, detections)
    mode = semslam.optimize(base, initial_values(poses, landmarks, detections)).values
    static_score = semslam.laplace_evidence_score(base, mode)
    result = {}
    for landmark in sorted(landmarks):
        own = [d for d in detections if d[1] == landmark]
        if len(own) < 3:
            continue
        graph = static_graph(motion, detections, skip_landmark=landmark)
        initial = semslam.Values()
        for key in mode.keys():
            initial.insert(key, mode[key])
        keys = [semslam.landmark_key(landmark)]
        for i in range(1, len(own)):
            keys.append(semslam.landmark_key(EXTRA_KEY_OFFSET + i))
            initial.insert(keys[-1], np.asarray(mode[keys[0]]))
        for key, detection in zip(keys, own):
            graph.add(detection_factor(detection, key))
        for i in range(1, len(own)):
            dt = max(steps[own[i][0]]["time"] - steps[own[i - 1][0]]["time"], 1e-3)
            graph.add(semslam.BetweenFactorPoint2(keys[i - 1], keys[i], np.zeros(2),
                                                  semslam.NoiseModel.isotropic(2, math.sqrt(q * dt))))
        walk = semslam.optimize(graph, initial).values
        result[landmark] = -0.5 * (semslam.laplace_evidence_score(graph, walk) - static_score)
    return result


def composition(detections, landmark):
    """Counter of the truth of a landmark's detections."""
    return collections.Counter(d[5] for d in detections if d[1] == landmark)


GROUPS = ["one real object (≥ 90 % of its detections)", "mostly real, several objects or some clutter",
          "mostly clutter"]


def group_of(counts):
    """Which of GROUPS a landmark's detections (a Counter of their truth) put it in; None without truth."""
    if not counts:
        return None
    truth, n = counts.most_common(1)[0]
    if truth in ("not-a-landmark",):
        return GROUPS[2]
    if truth in ("", "unknown"):
        return None
    return GROUPS[0] if n >= 0.9 * sum(counts.values()) else GROUPS[1]


def summary(evidence, detections, thresholds=(0.0, 5.0, 10.0)):
    """Per group: how many landmarks, how many with Δ above each threshold, the largest Δ."""
    rows = {g: [] for g in GROUPS}
    for landmark, delta in evidence.items():
        g = group_of(composition(detections, landmark))
        if g is not None:
            rows[g].append(delta)
    return [(g, len(v), [sum(d > t for d in v) for t in thresholds], max(v) if v else None) for g, v in rows.items()]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log", metavar="LOG")
    parser.add_argument("run", metavar="RUN_DIR")
    parser.add_argument("--q", type=float, default=0.005,
                        help="random-walk intensity, m²/s (default 0.005: about 0.07 m/s over a second)")
    parser.add_argument("--write-without-flagged", metavar="OUT",
                        help="also write the log without the detections on landmarks whose Δ exceeds --above")
    parser.add_argument("--above", type=float, default=5.0, help="the threshold on Δ for --write-without-flagged")
    args = parser.parse_args()
    if not (args.q > 0 and math.isfinite(args.q)):
        sys.exit(f"landmark_motion_evidence.py: --q must be a positive number, got {args.q}")
    try:
        header, steps, poses, landmarks, detections = read_run(args.log, args.run)
    except (OSError, ValueError, KeyError) as error:
        sys.exit(f"landmark_motion_evidence.py: {error}")
    evidence = random_walk_evidence(header, steps, poses, landmarks, detections, args.q)
    print("| landmark | detections | truth of its detections | ln p(random walk) − ln p(static) |")
    print("|---|---|---|---|")
    for landmark, delta in evidence.items():
        truth = ", ".join(f"{t}: {n}" for t, n in composition(detections, landmark).most_common())
        print(f"| {landmark} | {sum(1 for d in detections if d[1] == landmark)} | {truth} | {delta:.2f} |")
    print("\n| landmarks | count | Δ > 0 | Δ > 5 | Δ > 10 | largest Δ |\n|---|---|---|---|---|---|")
    for group, count, above, largest in summary(evidence, detections):
        shown = "–" if largest is None else f"{largest:.1f}"
        print(f"| {group} | {count} | " + " | ".join(str(a) for a in above) + f" | {shown} |")
    if args.write_without_flagged:
        flagged = {landmark for landmark, delta in evidence.items() if delta > args.above}
        counts = oracle_logs.edit(args.log, args.write_without_flagged,
                                  drop_detections=detections_on(detections, flagged))
        print(f"\nwrote {args.write_without_flagged}: {counts['detections_dropped']} detections of {len(flagged)} "
              f"landmarks with Δ > {args.above} dropped")


if __name__ == "__main__":
    main()
