"""python/landmark_motion_evidence.py on a hand-made run: a static landmark's detections favour the static point, a
landmark that drives away favours the random walk, the groups of the summary, the log written without the flagged
landmark's detections, and the refusals."""

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import landmark_motion_evidence as lme  # noqa: E402

STEPS = 20
RANGE_SIGMA, BEARING_SIGMA = 0.1, 0.01


def pose(k):
    return (0.5 * k, 0.0, 0.0)  # 0.5 m per second along x


def static_point(k):
    return (5.0, 2.0)


def moving_point(k):
    return (5.0, -2.0 - 0.1 * k)  # 0.1 m/s away from the path: 1.9 m over the run


def range_bearing(p, point):
    dx, dy = point[0] - p[0], point[1] - p[1]
    return [math.hypot(dx, dy), math.atan2(dy, dx) - p[2]]


def write_run(directory, dimension=2, poses_in_trajectory=STEPS, landmarks=(0, 1)):
    """A log and a run folder whose estimate is the truth; landmark 0 is static_point, 1 moving_point."""
    header = {"format": "semslam-log", "version": 2, "dimension": dimension, "classes": 1,
              "sensor": {"kind": "range-bearing", "body_to_sensor": [0.0, 0.0, 0.0], "max_range": 0.0,
                         "field_of_view": 0.0},
              "initial_pose": {"mean": list(pose(0)), "covariance": np.diag([1e-6] * 3).tolist()}}
    covariance = np.diag([RANGE_SIGMA ** 2, BEARING_SIGMA ** 2]).tolist()
    log = os.path.join(directory, "log.jsonl")
    run = os.path.join(directory, "run")
    os.makedirs(run)
    with open(log, "w") as f:
        f.write(json.dumps(header) + "\n")
        for k in range(STEPS):
            detections = [{"geometry": range_bearing(pose(k), static_point(k)), "covariance": covariance, "truth": 7},
                          {"geometry": range_bearing(pose(k), moving_point(k)), "covariance": covariance,
                           "truth": "not-a-landmark"}]
            step = {"time": float(k), "detections": [detections[i] for i in landmarks]}
            if k > 0:
                step["odometry"] = {"increment": [0.5, 0.0, 0.0], "covariance": np.diag([1e-4] * 3).tolist()}
            f.write(json.dumps(step) + "\n")
    with open(os.path.join(run, "trajectory.tum"), "w") as f:
        for k in range(poses_in_trajectory):
            x, y, theta = pose(k)
            f.write(f"{k} {x} {y} 0 0 0 {math.sin(theta / 2)} {math.cos(theta / 2)}\n")
    middle = moving_point(STEPS / 2)
    rows = {0: "0,5.0,2.0,0,1", 1: "1,%r,%r,0,1" % middle}
    with open(os.path.join(run, "landmarks.csv"), "w") as f:
        f.write("id,x,y,class,p_class\n" + "".join(rows[i] + "\n" for i in landmarks))
    truth = {0: "7", 1: "not-a-landmark"}
    with open(os.path.join(run, "associations.csv"), "w") as f:
        f.write("step,detection,landmark,weight,truth,chi2\n")
        for k in range(STEPS):
            for detection, landmark in enumerate(landmarks):
                f.write(f"{k},{detection},{landmark},1,{truth[landmark]},0\n")
    return log, run


def evidence_of(directory, landmarks):
    log, run = write_run(directory, landmarks=landmarks)
    header, steps, poses, mapped, detections = lme.read_run(log, run)
    return lme.random_walk_evidence(header, steps, poses, mapped, detections, q=0.005), detections


def test_a_static_landmark_favours_the_static_point(tmp_path):
    evidence, detections = evidence_of(str(tmp_path), landmarks=(0,))
    # Exact detections of a static point: the random walk's extra freedom only costs its Occam factor.
    assert evidence[0] < -10
    groups = {g: (count, above) for g, count, above, _ in lme.summary(evidence, detections)}
    assert groups[lme.GROUPS[0]] == (1, [0, 0, 0])


def test_a_landmark_that_drives_away_favours_the_random_walk(tmp_path):
    evidence, detections = evidence_of(str(tmp_path), landmarks=(1,))
    assert evidence[1] > 10  # 1.9 m of motion against σ_r = 0.1 m: no static point explains it
    groups = {g: (count, above) for g, count, above, _ in lme.summary(evidence, detections)}
    assert groups[lme.GROUPS[2]] == (1, [1, 1, 1])


def test_with_both_the_moving_one_has_the_larger_evidence(tmp_path):
    # Each landmark is tested with the others static: the moving one bends the poses, so the static one's test
    # gains too; the moving one's gains most, which is why a demotion would take the largest first and re-test.
    evidence, _ = evidence_of(str(tmp_path), landmarks=(0, 1))
    assert evidence[1] > evidence[0]


def test_the_log_without_the_flagged_landmarks_detections(tmp_path):
    log, run = write_run(str(tmp_path), landmarks=(0, 1))
    detections = lme.read_run(log, run)[4]
    assert lme.detections_on(detections, {1}) == {(k, 1) for k in range(STEPS)}
    out = str(tmp_path / "without.jsonl")
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python",
                          "landmark_motion_evidence.py")
    result = subprocess.run([sys.executable, "-B", script, log, run, "--write-without-flagged", out, "--above", "300"],
                            capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert result.returncode == 0, result.stderr
    assert f"{STEPS} detections of 1 landmarks with Δ > 300.0 dropped" in result.stdout  # the moving one only
    with open(out) as f:
        header, *steps = [json.loads(line) for line in f]
    assert [[d["truth"] for d in step["detections"]] for step in steps] == [[7]] * STEPS
    with open(log) as f:
        assert header == json.loads(next(f))


def test_the_run_must_be_a_2d_range_bearing_one_whose_trajectory_matches_the_log(tmp_path):
    log, run = write_run(str(tmp_path / "a"), dimension=3)
    with pytest.raises(ValueError, match="2D range-bearing"):
        lme.read_run(log, run)
    log, run = write_run(str(tmp_path / "b"), poses_in_trajectory=STEPS - 1)
    with pytest.raises(ValueError, match="19 poses for the log's 20 steps"):
        lme.read_run(log, run)


def test_group_of_reads_the_truth_of_a_landmarks_detections():
    from collections import Counter
    assert lme.group_of(Counter({"7": 9, "8": 1})) == lme.GROUPS[0]
    assert lme.group_of(Counter({"7": 8, "8": 2})) == lme.GROUPS[1]
    assert lme.group_of(Counter({"not-a-landmark": 5, "7": 4})) == lme.GROUPS[2]
    assert lme.group_of(Counter()) is None
