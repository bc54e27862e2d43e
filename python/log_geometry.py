"""Poses and detections of a measurement log (docs/measurement-log.md) in plain Python: a detection's point in the
sensor frame, a pose applied to a point and its inverse, and the polar coordinates the sensor field is stated in.
No numpy, so that the diagnostic scripts run on any python3.

Poses as the log writes them: 2D [x, y, θ]; 3D [x, y, z, qx, qy, qz, qw] (the rotation body → world, a unit
quaternion). Points are tuples of 2 or 3 floats.
"""
import math


def rotate(q, p):
    """The rotation of the unit quaternion q = (qx, qy, qz, qw) applied to p."""
    x, y, z, w = q
    px, py, pz = p
    # v' = v + 2 w (u × v) + 2 u × (u × v), u = (x, y, z)
    cx, cy, cz = y * pz - z * py, z * px - x * pz, x * py - y * px
    ccx, ccy, ccz = y * cz - z * cy, z * cx - x * cz, x * cy - y * cx
    return (px + 2 * (w * cx + ccx), py + 2 * (w * cy + ccy), pz + 2 * (w * cz + ccz))


def world(pose, p):
    """pose · p: a point of the pose's frame in the frame the pose is given in (2D or 3D by the pose's length)."""
    if len(pose) == 3:
        c, s = math.cos(pose[2]), math.sin(pose[2])
        return (pose[0] + c * p[0] - s * p[1], pose[1] + s * p[0] + c * p[1])
    r = rotate(pose[3:], p)
    return (pose[0] + r[0], pose[1] + r[1], pose[2] + r[2])


def local(pose, p):
    """pose⁻¹ · p: a point of the outer frame in the pose's frame."""
    if len(pose) == 3:
        c, s = math.cos(pose[2]), math.sin(pose[2])
        dx, dy = p[0] - pose[0], p[1] - pose[1]
        return (c * dx + s * dy, -s * dx + c * dy)
    qx, qy, qz, qw = pose[3:]
    return rotate((-qx, -qy, -qz, qw), (p[0] - pose[0], p[1] - pose[1], p[2] - pose[2]))


def sensor_point(kind, geometry):
    """The detected point in the sensor frame, for the point-measuring sensor kinds (a relative pose: its
    position)."""
    if kind == "range-bearing":
        r, b = geometry
        return (r * math.cos(b), r * math.sin(b))
    if kind == "range-bearing-elevation":
        r, b, e = geometry
        return (r * math.cos(e) * math.cos(b), r * math.cos(e) * math.sin(b), r * math.sin(e))
    if kind == "relative-position":
        return tuple(geometry)
    if kind == "relative-pose":
        return tuple(geometry[:2]) if len(geometry) == 3 else tuple(geometry[:3])
    raise ValueError(f"unknown sensor kind {kind!r}")


def polar(p):
    """(range, bearing, elevation) of a sensor-frame point (elevation 0 in 2D)."""
    horizontal = math.hypot(p[0], p[1])
    elevation = math.atan2(p[2], horizontal) if len(p) == 3 else 0.0
    return math.hypot(horizontal, p[2] if len(p) == 3 else 0.0), math.atan2(p[1], p[0]), elevation
