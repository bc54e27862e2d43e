"""python/confirmation_ceiling.py and python/log_geometry.py on hand-made logs (no data needed): which real
detections the confirmation rule can confirm, which detections never come into the sensor's field again, the
field taken from the header or from the log, the 2D and 3D frames; and the KITTI tracking read-out's paragraph
built from them (python/results_kitti_tracking.py, ceiling_lines).

Usage: test_confirmation_ceiling.py
"""
import json
import math
import os
import random
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import confirmation_ceiling  # noqa: E402
import log_geometry  # noqa: E402
import results_kitti_tracking  # noqa: E402


def write_log(directory, header, steps):
    path = os.path.join(directory, "log.jsonl")
    with open(path, "w") as f:
        f.write(json.dumps(header) + "\n")
        for step in steps:
            f.write(json.dumps(step) + "\n")
    return path


def detection(range_, bearing, truth, source=None):
    d = {"geometry": [range_, bearing], "covariance": [[0.01, 0.0], [0.0, 0.0001]], "label": 0, "truth": truth}
    if source is not None:
        d["clutter_source"] = source
    return d


HEADER_2D = {"format": "semslam-log", "version": 2, "dimension": 2, "classes": 1,
             "sensor": {"kind": "range-bearing", "body_to_sensor": [0.0, 0.0, 0.0], "max_range": 10.0,
                        "field_of_view": 1.0}}

# t = 0 at the origin facing +x: A (truth 1), B (2), C (3), a moving object, a false positive, an unknown one.
# t = 0.5 turned by -0.3 rad: C again, at bearing -0.1 (0.5 s after its first: not a second sighting for Δt = 1 s);
# B's point now lies at bearing 0.7, outside ±0.5, the moving object's at 0.4, inside, the false positive's at 0.75,
# outside.
# t = 2, the same pose: A again, at bearing 0.3 (its second sighting).
# t = 3 without a true pose: not a look at anything.
STEPS_2D = [
    {"time": 0.0, "true_pose": [0.0, 0.0, 0.0],
     "detections": [detection(5.0, 0.0, 1), detection(5.0, 0.4, 2), detection(5.0, -0.4, 3),
                    detection(4.0, 0.1, "not-a-landmark", source=7), detection(6.0, 0.45, "not-a-landmark"),
                    detection(3.0, 0.0, "unknown")]},
    {"time": 0.5, "odometry": {"increment": [0.0, 0.0, -0.3], "covariance": [[1e-4, 0, 0], [0, 1e-4, 0], [0, 0, 1e-4]]},
     "true_pose": [0.0, 0.0, -0.3], "detections": [detection(5.0, -0.1, 3)]},
    {"time": 2.0, "odometry": {"increment": [0.0, 0.0, 0.0], "covariance": [[1e-4, 0, 0], [0, 1e-4, 0], [0, 0, 1e-4]]},
     "true_pose": [0.0, 0.0, -0.3], "detections": [detection(5.0, 0.3, 1)]},
    {"time": 3.0, "odometry": {"increment": [0.0, 0.0, 0.0], "covariance": [[1e-4, 0, 0], [0, 1e-4, 0], [0, 0, 1e-4]]},
     "detections": []},
]


class Ceiling(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.scratch.cleanup()

    def test_counts_on_a_hand_made_2d_log(self):
        c = confirmation_ceiling.ceiling(write_log(self.scratch.name, HEADER_2D, STEPS_2D))
        self.assertEqual(c["real"], 5)  # A twice, B, C twice; the unknown one left out
        self.assertEqual(c["real_confirmable"], 2)  # A's two, 2 s apart
        self.assertAlmostEqual(c["ceiling"], 0.4)
        self.assertEqual(c["real_never_in_view_again"], 1)  # B; C's first sighting is in view at t = 0.5
        self.assertEqual((c["moving"], c["moving_never_in_view_again"]), (1, 0))
        self.assertEqual((c["false_positive"], c["false_positive_never_in_view_again"]), (1, 1))

    def test_the_spacing_decides_what_is_confirmable(self):
        path = write_log(self.scratch.name, HEADER_2D, STEPS_2D)
        self.assertAlmostEqual(confirmation_ceiling.ceiling(path, spacing=0.5)["ceiling"], 0.8)  # A and C
        self.assertAlmostEqual(confirmation_ceiling.ceiling(path, spacing=2.5)["ceiling"], 0.0)

    def test_the_field_comes_from_the_log_where_the_header_states_none(self):
        header = json.loads(json.dumps(HEADER_2D))
        header["sensor"]["max_range"] = 0.0
        header["sensor"]["field_of_view"] = 0.0
        max_range, fov, _ = confirmation_ceiling.sensor_field(header, STEPS_2D)
        self.assertAlmostEqual(max_range, 6.0)
        self.assertAlmostEqual(fov, 0.9)
        # With the observed ±0.45 rad the moving object's point (bearing 0.4 once turned) is still in view, the
        # false positive's (0.75) not.
        c = confirmation_ceiling.ceiling(write_log(self.scratch.name, header, STEPS_2D))
        self.assertEqual((c["moving_never_in_view_again"], c["false_positive_never_in_view_again"]), (0, 1))

    def test_a_range_limit_hides_a_point(self):
        header = json.loads(json.dumps(HEADER_2D))
        header["sensor"]["max_range"] = 4.5  # C's point, 5 m away, is then out of range when turned
        c = confirmation_ceiling.ceiling(write_log(self.scratch.name, header, STEPS_2D))
        self.assertEqual(c["real_never_in_view_again"], 3)  # B, and C's two

    def test_no_real_detection_gives_no_ceiling(self):
        steps = [{"time": 0.0, "true_pose": [0.0, 0.0, 0.0], "detections": [detection(4.0, 0.1, "not-a-landmark")]}]
        self.assertIsNone(confirmation_ceiling.ceiling(write_log(self.scratch.name, HEADER_2D, steps))["ceiling"])

    def test_3d_relative_position_through_a_rotated_sensor(self):
        # The sensor looks along the body's −y axis (body_to_sensor: a −90° yaw about z): a detection 5 m ahead of
        # it, seen from the origin, is the world point (0, −5, 0). From (0, −10, 0) facing −x (yaw 180°) the sensor
        # looks along +y, straight at it; facing +x it looks along −y, away. (Were body_to_sensor ignored, the point
        # would be (5, 0, 0), out of view from (0, −10, 0) facing −x.)
        half = math.sqrt(0.5)
        header = {"format": "semslam-log", "version": 2, "dimension": 3, "classes": 1,
                  "sensor": {"kind": "relative-position", "body_to_sensor": [0, 0, 0, 0, 0, -half, half],
                             "max_range": 0.0, "field_of_view": 1.0}}
        ahead = {"geometry": [5.0, 0.0, 0.0], "covariance": [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.01]], "label": 0,
                 "truth": 1}
        first = {"time": 0.0, "true_pose": [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0], "detections": [ahead]}
        facing_minus_x = {"time": 1.0, "true_pose": [0.0, -10.0, 0.0, 0.0, 0.0, 1.0, 0.0], "detections": []}
        facing_plus_x = {"time": 1.0, "true_pose": [0.0, -10.0, 0.0, 0.0, 0.0, 0.0, 1.0], "detections": []}
        c = confirmation_ceiling.ceiling(write_log(self.scratch.name, header, [first, facing_minus_x]))
        self.assertEqual(c["real_never_in_view_again"], 0)
        c = confirmation_ceiling.ceiling(write_log(self.scratch.name, header, [first, facing_plus_x]))
        self.assertEqual(c["real_never_in_view_again"], 1)

    def test_local_inverts_world(self):
        rng = random.Random(4)
        for _ in range(50):
            pose2 = [rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-3, 3)]
            q = [rng.gauss(0, 1) for _ in range(4)]
            norm = math.sqrt(sum(x * x for x in q))
            pose3 = [rng.uniform(-5, 5) for _ in range(3)] + [x / norm for x in q]
            for pose, point in ((pose2, (1.5, -2.0)), (pose3, (1.5, -2.0, 0.7))):
                back = log_geometry.local(pose, log_geometry.world(pose, point))
                for a, b in zip(back, point):
                    self.assertAlmostEqual(a, b, places=12)

    def test_the_read_out_paragraph_counts_what_the_logs_hold(self):
        path = write_log(self.scratch.name, HEADER_2D, STEPS_2D)
        text = "\n".join(results_kitti_tracking.ceiling_lines({(0, results_kitti_tracking.READOUT): (path, None)},
                                                              [0]))
        self.assertIn("3 of the 5 real detections", text)
        self.assertIn("ceiling on `da_accuracy_real` is 0.400", text)
        self.assertIn("Of those 3, 1 never come", text)
        self.assertIn("0 of the 1 moving-clutter and 1 of the 1 false-positive", text)
        self.assertIn("at most 0.600 on `da_accuracy_real` and at most 1.000 on moving clutter", text)
        self.assertIn("in about the proportion 0 : 1 to the real sightings", text)


if __name__ == "__main__":
    unittest.main()
