"""python/oracle_logs.py on hand-made logs (no data needed): clutter dropped and nothing else, odometry replaced by
the true relative motion (composing it onto the previous true pose gives the next) and kept next to a step without
truth, the stated covariance kept, 3D refused; a constant odometry bias removed exactly and one that changes faster
than the window only in part; detections dropped by their (step, index); and the table of
python/results_association_oracles.py on hand-made metrics, its sum of the random-walk evidence summaries of several
runs, and its accuracy with dropped real detections counted as wrong.

Usage: test_oracle_logs.py
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import oracle_logs  # noqa: E402
import results_association_oracles as section  # noqa: E402

COVARIANCE = [[1e-3, 0.0, 0.0], [0.0, 2e-3, 0.0], [0.0, 0.0, 3e-3]]
HEADER = {"format": "semslam-log", "version": 2, "dimension": 2, "classes": 1,
          "sensor": {"kind": "range-bearing", "body_to_sensor": [0.0, 0.0, 0.0], "max_range": 0.0,
                     "field_of_view": 0.0}}


def detection(truth, range_=2.0):
    return {"geometry": [range_, 0.1], "covariance": [[0.01, 0.0], [0.0, 0.0001]], "label": 0, "truth": truth}


def steps():
    return [
        {"time": 0.0, "true_pose": [1.0, 2.0, 3.0], "detections": [detection(4), detection("not-a-landmark")]},
        {"time": 1.0, "odometry": {"increment": [0.5, 0.0, 0.1], "covariance": COVARIANCE},
         "true_pose": [1.2, 1.9, -3.1], "detections": [detection("unknown"), detection(4, 2.5)]},
        {"time": 2.0, "odometry": {"increment": [0.4, 0.0, -0.2], "covariance": COVARIANCE},
         "detections": [detection("not-a-landmark"), detection("not-a-landmark")]},
        {"time": 3.0, "odometry": {"increment": [0.3, 0.1, 0.0], "covariance": COVARIANCE},
         "true_pose": [1.5, 1.5, 2.0], "detections": []},
        {"time": 4.0, "odometry": {"increment": [0.3, 0.1, 0.0], "covariance": COVARIANCE},
         "true_pose": [1.9, 1.0, 2.5], "detections": []},
    ]


def compose(a, d):
    c, s = math.cos(a[2]), math.sin(a[2])
    return [a[0] + c * d[0] - s * d[1], a[1] + s * d[0] + c * d[1], a[2] + d[2]]


class OracleLogs(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()
        self.source = os.path.join(self.scratch.name, "log.jsonl")
        with open(self.source, "w") as f:
            f.write(json.dumps(HEADER) + "\n")
            for step in steps():
                f.write(json.dumps(step) + "\n")
        self.out = os.path.join(self.scratch.name, "out.jsonl")

    def tearDown(self):
        self.scratch.cleanup()

    def read(self):
        with open(self.out) as f:
            return [json.loads(line) for line in f]

    def test_drop_clutter_removes_clutter_only(self):
        counts = oracle_logs.edit(self.source, self.out, drop_clutter=True)
        self.assertEqual(counts["clutter_dropped"], 3)
        header, *edited = self.read()
        self.assertEqual(header, HEADER)
        self.assertEqual([[d["truth"] for d in s["detections"]] for s in edited], [[4], ["unknown", 4], [], [], []])
        self.assertEqual(edited[1]["detections"][1]["geometry"], [2.5, 0.1])
        self.assertEqual([s["odometry"]["increment"] for s in edited[1:]],
                         [s["odometry"]["increment"] for s in steps()[1:]])

    def test_true_odometry_composes_to_the_next_true_pose(self):
        counts = oracle_logs.edit(self.source, self.out, true_odometry=True)
        self.assertEqual((counts["odometry_replaced"], counts["odometry_kept"]), (2, 2))
        _, *edited = self.read()
        original = steps()
        for k in (1, 4):  # both neighbours have a true pose
            predicted = compose(original[k - 1]["true_pose"], edited[k]["odometry"]["increment"])
            truth = original[k]["true_pose"]
            self.assertAlmostEqual(predicted[0], truth[0], places=12)
            self.assertAlmostEqual(predicted[1], truth[1], places=12)
            self.assertAlmostEqual(math.remainder(predicted[2] - truth[2], 2 * math.pi), 0.0, places=12)
            self.assertLessEqual(abs(edited[k]["odometry"]["increment"][2]), math.pi)
        self.assertAlmostEqual(edited[1]["odometry"]["increment"][2], 2 * math.pi - 6.1, places=12)  # wrapped
        for k in (2, 3):  # step 2 has no true pose: its increment and the next are kept
            self.assertEqual(edited[k]["odometry"]["increment"], original[k]["odometry"]["increment"])
        self.assertTrue(all(s["odometry"]["covariance"] == COVARIANCE for s in edited[1:]))
        self.assertEqual(len(edited[0]["detections"]), 2)  # detections untouched

    def test_3d_odometry_is_refused_and_nothing_is_written(self):
        header = dict(HEADER, dimension=3)
        with open(self.source, "w") as f:
            f.write(json.dumps(header) + "\n")
        with self.assertRaisesRegex(ValueError, "2D logs"):
            oracle_logs.edit(self.source, self.out, true_odometry=True)
        self.assertFalse(os.path.exists(self.out))
        result = subprocess.run([sys.executable, "-B", os.path.join(HERE, "..", "..", "python", "oracle_logs.py"),
                                 self.source, self.out, "--true-odometry"], capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("dimension 3", result.stderr)

    def write_biased_log(self, bias_of_time, count=40, period=1.0):
        """A log whose true motion turns and drives, with the odometry off by bias_of_time(t) per second (x, y, θ)."""
        poses, log = [[0.0, 0.0, 0.0]], []
        for k in range(count):
            t = k * period
            step = {"time": t, "true_pose": poses[-1], "detections": []}
            if k > 0:
                truth = oracle_logs.relative_pose_2d(poses[-2], poses[-1])
                bias = bias_of_time(t)
                step["odometry"] = {"increment": [truth[c] + bias[c] * period for c in range(3)],
                                    "covariance": COVARIANCE}
            log.append(step)
            poses.append(compose(poses[-1], [0.3, 0.0, 0.2 * math.sin(0.3 * k)]))
        with open(self.source, "w") as f:
            f.write(json.dumps(HEADER) + "\n")
            for step in log:
                f.write(json.dumps(step) + "\n")
        return log

    def odometry_errors(self):
        _, *edited = self.read()
        errors = []
        for previous, step in zip(edited, edited[1:]):
            truth = oracle_logs.relative_pose_2d(previous["true_pose"], step["true_pose"])
            u = step["odometry"]["increment"]
            errors.append([u[0] - truth[0], u[1] - truth[1], math.remainder(u[2] - truth[2], 2 * math.pi)])
        return errors

    def test_a_constant_odometry_bias_is_removed_exactly(self):
        self.write_biased_log(lambda t: [0.02, -0.01, 0.005])
        counts = oracle_logs.edit(self.source, self.out, odometry_bias_window=10.0)
        self.assertEqual(counts["odometry_debiased"], 39)
        for error in self.odometry_errors():
            for e in error:
                self.assertAlmostEqual(e, 0.0, places=12)
        _, *edited = self.read()
        self.assertTrue(all(s["odometry"]["covariance"] == COVARIANCE for s in edited[1:]))

    def test_a_bias_faster_than_the_window_is_removed_in_part(self):
        # A heading bias alternating sign every step averages out over 10 s and is kept; a slow ramp is followed.
        self.write_biased_log(lambda t: [0.0, 0.0, 0.01 * (-1) ** int(t) + 0.001 * t])
        oracle_logs.edit(self.source, self.out, odometry_bias_window=10.0)
        errors = [e[2] for e in self.odometry_errors()]
        for k, e in enumerate(errors[5:-5], start=6):  # away from the ends, where the window is whole
            self.assertAlmostEqual(abs(e), 0.01, delta=0.0012)  # the alternating part stays, the ramp is gone
            self.assertEqual(e > 0, k % 2 == 0)

    def test_the_bias_edit_is_refused_where_it_does_not_apply(self):
        with self.assertRaisesRegex(ValueError, "positive number of seconds"):
            oracle_logs.edit(self.source, self.out, odometry_bias_window=0.0)
        with self.assertRaisesRegex(ValueError, "choose one"):
            oracle_logs.edit(self.source, self.out, true_odometry=True, odometry_bias_window=5.0)
        self.assertFalse(os.path.exists(self.out))

    def test_detections_are_dropped_by_step_and_index(self):
        counts = oracle_logs.edit(self.source, self.out, drop_detections={(0, 1), (1, 0), (2, 1), (3, 0)})
        self.assertEqual(counts["detections_dropped"], 3)  # step 3 has no detection 0
        _, *edited = self.read()
        self.assertEqual([[d["truth"] for d in s["detections"]] for s in edited],
                         [[4], [4], ["not-a-landmark"], [], []])
        self.assertEqual(edited[1]["detections"][0]["geometry"], [2.5, 0.1])

    def test_the_section_table_means_over_seeds_and_robots(self):
        results = {}
        for robot in section.ROBOTS:
            for seed in section.SEEDS:
                results[("as recorded", robot, seed)] = {
                    "da_accuracy_real": 0.1 * robot + 0.01 * seed, "ate_rmse": 1.0, "clutter_rejected": 0.5,
                    "landmarks_split": 2, "landmarks_merged": 1, "landmarks_estimated": 30}
        lines = section.table(results)
        self.assertEqual(len(lines), 3)  # header, rule, the one variant with runs
        cells = [c.strip() for c in lines[2].strip("|").split("|")]
        self.assertEqual(cells[0], "as recorded")
        self.assertEqual(cells[1:6], ["0.120", "0.220", "0.320", "0.420", "0.520"])
        self.assertEqual(cells[6], "0.320")
        self.assertEqual(cells[7:], ["1.000", "0.500", "2.0 / 1.0", "30.0"])

    def test_summaries_of_several_runs_add_up(self):
        one = [("a", 3, [2, 1, 0], 4.5), ("b", 1, [0, 0, 0], None)]
        two = [("a", 2, [1, 1, 1], 12.0), ("b", 4, [3, 2, 0], 7.0), ("c", 1, [1, 0, 0], 0.5)]
        self.assertEqual(section.add_summaries([one, two]),
                         [("a", 5, [3, 2, 1], 12.0), ("b", 5, [3, 2, 0], 7.0), ("c", 1, [1, 0, 0], 0.5)])
        self.assertEqual(section.add_summaries([]), [])

    def test_dropped_real_detections_count_as_wrong(self):
        # 60 real detections left, 45 of them right; 20 real ones dropped: 45 of 80.
        metrics = {"da_total": 100, "da_clutter": 40, "da_accuracy_real": 0.75}
        self.assertAlmostEqual(section.accuracy_with_dropped_as_wrong(metrics, 20), 45 / 80, places=15)
        self.assertAlmostEqual(section.accuracy_with_dropped_as_wrong(metrics, 0), 0.75, places=15)
        self.assertIsNone(section.accuracy_with_dropped_as_wrong({"da_total": 5, "da_clutter": 5,
                                                                  "da_accuracy_real": None}, 0))
        # Which detections on the flagged landmarks are real: truth 4 twice; clutter, "unknown" and no truth are not.
        # (step, landmark, range, bearing, covariance, truth, detection index), as landmark_motion_evidence reads them
        detections = [(0, 1, 2.0, 0.1, None, "4", 0), (0, 1, 2.0, 0.1, None, "not-a-landmark", 1),
                      (1, 2, 2.0, 0.1, None, "unknown", 0), (1, 2, 2.5, 0.1, None, "4", 1),
                      (2, 3, 2.0, 0.1, None, "", 0), (3, 5, 2.0, 0.1, None, "4", 0)]
        self.assertEqual(section.real_detections_on(detections, {1, 2, 3}), 2)


if __name__ == "__main__":
    unittest.main()
