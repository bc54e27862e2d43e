#!/usr/bin/env python3
"""What the provisional-landmark rule can reach on a measurement log, read from the log and its truth alone (no run).

The unassigned birth rule (docs/association-front-end.md §5) confirms a provisional landmark once M = 2 of its
detections are at least Δt apart (default 1 s) and drops it otherwise; `da_accuracy_real` counts a real detection on
a dropped landmark as wrong (docs/metrics.md). Two properties of each detection follow from the log:

- **confirmable** (real detections): its true landmark has two detections at least Δt apart in the log. Under the
  rule a real detection that is not confirmable ends on a dropped landmark whatever the method and the odometry, so
  the fraction of confirmable real detections is the rule's ceiling on `da_accuracy_real` (up to the identity
  matching of the metric, which may credit a detection on a landmark that another object's detections confirmed);
- **never in view again**: at no later step with a true pose does the detection's world point (through its step's
  true pose) lie in the sensor's field: range ≤ r_max, |bearing| ≤ Φ/2 and, in 3D, |elevation| ≤ Ψ/2, each as the
  front end takes it (`UnassignedHypothesis::inField`): the header's `max_range` and `field_of_view` where stated,
  else the largest range and twice the largest |bearing| of the log's detections; Ψ twice the largest |elevation|.
  No missed detection can ever refute such a sighting, so time and geometry cannot tell a real one seen once from
  clutter seen once: their counts are the odds any rule faces there.

On a log whose reference trajectory is an estimate (KITTI tracking: ORB-SLAM3's), "in view" is through that estimate.

Usage: python3 python/confirmation_ceiling.py LOG [LOG ...] [--spacing SECONDS]
Plain Python 3.
"""
import argparse
import collections
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from log_geometry import local, polar, sensor_point, world  # noqa: E402

DEFAULT_SPACING = 1.0  # seconds: the rule's default Δt (--confirmation-spacing)


def read_log(path):
    """(header, steps) of a measurement log (JSON lines)."""
    with open(path) as f:
        header = json.loads(next(f))
        return header, [json.loads(line) for line in f]


def truth_kind(detection):
    """'real', 'moving' (not-a-landmark with a clutter_source), 'false_positive' (not-a-landmark without), or None
    (unknown or no truth: left out, as the metrics do)."""
    truth = detection.get("truth")
    if truth == "not-a-landmark":
        return "moving" if "clutter_source" in detection else "false_positive"
    if truth is None or truth == "unknown":
        return None
    return "real"


def sensor_field(header, steps):
    """(r_max, Φ, Ψ): the header's range and field of view where stated, else the log's observed extremes."""
    kind = header["sensor"]["kind"]
    ranges, bearings, elevations = [0.0], [0.0], [0.0]
    for step in steps:
        for detection in step["detections"]:
            r, b, e = polar(sensor_point(kind, detection["geometry"]))
            ranges.append(r)
            bearings.append(abs(b))
            elevations.append(abs(e))
    stated_range = header["sensor"].get("max_range", 0.0)
    stated_fov = header["sensor"].get("field_of_view", 0.0)
    return (stated_range if stated_range > 0 else max(ranges),
            min(stated_fov if stated_fov > 0 else 2 * max(bearings), 2 * math.pi),
            min(2 * max(elevations), math.pi))


def ceiling(path, spacing=DEFAULT_SPACING):
    """Counts of one log: real detections, the confirmable ones, and per truth kind the detections never in view
    again (real ones among the unconfirmable only: a confirmable one needs no second look); plus `ceiling`, the
    fraction of confirmable real detections (None without real detections)."""
    header, steps = read_log(path)
    kind = header["sensor"]["kind"]
    body_to_sensor = header["sensor"].get("body_to_sensor")
    max_range, fov, elevation_span = sensor_field(header, steps)
    times = collections.defaultdict(list)
    for step in steps:
        for detection in step["detections"]:
            if truth_kind(detection) == "real":
                times[detection["truth"]].append(step["time"])
    confirmable = {landmark for landmark, t in times.items() if max(t) - min(t) >= spacing}

    def in_field(pose, point):
        sensor_pose_point = local(pose, point)
        if body_to_sensor:
            sensor_pose_point = local(body_to_sensor, sensor_pose_point)
        r, b, e = polar(sensor_pose_point)
        return r <= max_range and abs(b) <= fov / 2 and (len(point) == 2 or abs(e) <= elevation_span / 2)

    def seen_again(k, point):
        return any(later.get("true_pose") and in_field(later["true_pose"], point) for later in steps[k + 1:])

    counts = collections.Counter()
    for k, step in enumerate(steps):
        for detection in step["detections"]:
            what = truth_kind(detection)
            if what is None:
                continue
            counts[what] += 1
            if what == "real" and detection["truth"] in confirmable:
                counts["real_confirmable"] += 1
                continue
            pose = step.get("true_pose")
            if pose is None:
                continue
            p = sensor_point(kind, detection["geometry"])
            point = world(pose, world(body_to_sensor, p) if body_to_sensor else p)
            if not seen_again(k, point):
                counts[f"{what}_never_in_view_again"] += 1
    result = {key: counts[key] for key in ("real", "real_confirmable", "real_never_in_view_again", "moving",
                                           "moving_never_in_view_again", "false_positive",
                                           "false_positive_never_in_view_again")}
    result["ceiling"] = counts["real_confirmable"] / counts["real"] if counts["real"] else None
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("logs", nargs="+", metavar="LOG")
    parser.add_argument("--spacing", type=float, default=DEFAULT_SPACING, help="Δt of the rule, seconds (default 1)")
    args = parser.parse_args()
    if not args.spacing >= 0:
        sys.exit(f"confirmation_ceiling.py: --spacing must be ≥ 0, got {args.spacing}")
    print("| log | real | confirmable | ceiling | real seen once, never in view again | moving (never in view again) "
          "| false positives (never in view again) |")
    print("|---|---|---|---|---|---|---|")
    ceilings = []
    for path in args.logs:
        if not os.path.exists(path):
            sys.exit(f"confirmation_ceiling.py: {path}: no such file")
        c = ceiling(path, args.spacing)
        if c["ceiling"] is not None:
            ceilings.append(c["ceiling"])
        shown = "—" if c["ceiling"] is None else f"{c['ceiling']:.3f}"
        print(f"| {path} | {c['real']} | {c['real_confirmable']} | {shown} | {c['real_never_in_view_again']} | "
              f"{c['moving']} ({c['moving_never_in_view_again']}) | {c['false_positive']} "
              f"({c['false_positive_never_in_view_again']}) |")
    if ceilings:
        print(f"\nmean ceiling over the {len(ceilings)} logs with real detections: "
              f"{sum(ceilings) / len(ceilings):.3f}")


if __name__ == "__main__":
    main()
