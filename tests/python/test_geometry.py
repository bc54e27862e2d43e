"""Geometry through Python: the group laws, exp/log round trips, matrices against numpy, pose arrays."""

import math

import numpy as np
import pytest

import semslam

RNG = np.random.default_rng(7)


def random_se2():
    x, y = RNG.normal(size=2)
    return semslam.SE2(x, y, RNG.uniform(-math.pi, math.pi))


def random_se3():
    return semslam.SE3.exp(RNG.normal(size=6))


@pytest.mark.parametrize("make", [random_se2, random_se3,
                                  lambda: semslam.SO2(RNG.uniform(-3, 3)),
                                  lambda: semslam.SO3.exp(RNG.normal(size=3))])
def test_group_laws_match_the_matrices(make):
    for _ in range(20):
        a, b = make(), make()
        np.testing.assert_allclose((a * b).matrix(), a.matrix() @ b.matrix(), atol=1e-12)
        np.testing.assert_allclose(a.compose(b).matrix(), (a * b).matrix(), atol=0)
        np.testing.assert_allclose(a.inverse().matrix(), np.linalg.inv(a.matrix()), atol=1e-12)
        np.testing.assert_allclose(a.between(b).matrix(), np.linalg.inv(a.matrix()) @ b.matrix(), atol=1e-12)
        assert type(a).exp(a.log()).equals(a, 1e-12)
        delta = a.local_coordinates(b)
        assert a.retract(delta).equals(b, 1e-9)


def test_se2_fields_and_exp_of_a_pure_translation():
    pose = semslam.SE2(1.0, -2.0, 0.5)
    assert (pose.x(), pose.y(), pose.theta()) == (1.0, -2.0, 0.5)
    np.testing.assert_array_equal(pose.vector(), [1.0, -2.0, 0.5])
    np.testing.assert_array_equal(semslam.SE2.exp(np.array([0.3, 0.4, 0.0])).vector(), [0.3, 0.4, 0.0])
    point = np.array([0.2, 0.7])
    np.testing.assert_allclose(pose.transform_to(pose.transform_from(point)), point, atol=1e-15)
    assert semslam.SE2.dimension == 3 and semslam.SE3.dimension == 6


def test_so3_quaternion_round_trip():
    for _ in range(20):
        rotation = semslam.SO3.exp(RNG.normal(size=3))
        qx, qy, qz, qw = rotation.quaternion()
        assert semslam.SO3.from_quaternion(qx, qy, qz, qw).equals(rotation, 1e-12)
        assert semslam.SO3(rotation.matrix()).equals(rotation, 1e-12)


def test_wrong_sizes_and_numbers_raise_instead_of_crashing():
    with pytest.raises(TypeError):
        semslam.SE2.exp(np.zeros(2))
    with pytest.raises(TypeError):
        semslam.SE3.exp(np.zeros(3))
    with pytest.raises(ValueError, match="finite"):
        semslam.SE3(np.full((4, 4), np.nan))
    with pytest.raises(ValueError, match="finite"):
        semslam.SO3(np.full((3, 3), np.inf))
    with pytest.raises(ValueError, match="bottom row"):
        semslam.SE3(np.ones((4, 4)))
    matrix = random_se3().matrix()
    assert semslam.SE3(matrix).equals(semslam.SE3(semslam.SO3(matrix[:3, :3]), matrix[:3, 3]), 0)


def test_trajectory_arrays_round_trip():
    poses = [random_se3() for _ in range(5)]
    rows = np.array([np.r_[p.translation(), p.rotation().quaternion()] for p in poses])
    trajectory = semslam.Trajectory(np.arange(5.0), rows)
    np.testing.assert_allclose(trajectory.xyz_quaternions[:, :3], rows[:, :3], atol=1e-15)
    np.testing.assert_allclose(trajectory.matrices, np.array([p.matrix() for p in poses]), atol=1e-12)
    again = semslam.Trajectory(trajectory.timestamps, trajectory.matrices)
    np.testing.assert_allclose(again.positions, trajectory.positions, atol=0)
    planar = semslam.Trajectory(np.arange(3.0), np.array([[0, 0, 0], [1, 0, math.pi / 2], [1, 1, math.pi]]))
    np.testing.assert_allclose(planar.positions, [[0, 0, 0], [1, 0, 0], [1, 1, 0]], atol=1e-15)
    with pytest.raises(ValueError, match="N×3"):
        semslam.Trajectory(np.arange(2.0), np.zeros((2, 5)))
    with pytest.raises(ValueError):
        semslam.Trajectory(np.arange(3.0), np.zeros((2, 7)))
