#pragma once
// A trajectory: a sequence of timestamped poses, the object every metric of the eval layer works on.
//
// It mirrors evo's PoseTrajectory3D (evo/core/trajectory.py): pose i is the SE3 T_i = [R_i t_i; 0 1], the pose of
// the body in the world frame (x_world = R_i x_body + t_i). Like evo's `poses_se3`, rotations are kept exactly as
// read and are NOT re-orthonormalised (SO3's matrix constructor stores the matrix as given): KITTI files carry
// rotations rounded to 7-9 digits, and evo's published numbers (sse in particular, to 1e-6) depend on using them
// as they are.
//
// Timestamps are in seconds. A KITTI file without a time column has none: its trajectory is evo's PosePath3D, the
// index is used as time (0, 1, 2, ...) and hasTimestamps() is false, so that association pairs poses by index.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "semslam/geometry/Matrix.h"
#include "semslam/geometry/SE3.h"

namespace semslam {

class Trajectory {
 public:
  Trajectory() = default;
  /// One timestamp (seconds) per pose. Throws InputError when the sizes differ or a number is not finite.
  Trajectory(std::vector<double> timestamps, std::vector<SE3> poses, bool hasTimestamps = true);
  /// Poses without times: the index is the time (evo's PosePath3D).
  static Trajectory withoutTimestamps(std::vector<SE3> poses);

  std::size_t size() const { return poses_.size(); }
  bool empty() const { return poses_.empty(); }
  bool hasTimestamps() const { return hasTimestamps_; }

  const std::vector<double>& timestamps() const { return timestamps_; }
  double timestamp(std::size_t i) const { return timestamps_[i]; }
  const std::vector<SE3>& poses() const { return poses_; }
  const SE3& pose(std::size_t i) const { return poses_[i]; }
  const Point3& position(std::size_t i) const { return poses_[i].translation(); }
  /// All positions as the columns of a 3 x n matrix.
  Eigen::Matrix3Xd positions() const;

  /// The poses at `ids` (in that order; repeats allowed), as evo's reduce_to_ids.
  Trajectory subset(const std::vector<std::size_t>& ids) const;
  /// T_i <- A T_i for every pose (evo's transform with right_mul=False).
  void transform(const SE3& a);
  /// t_i <- s t_i for every pose, rotations unchanged (evo's scale).
  void scale(double s);
  /// Sum of the distances between consecutive positions (evo's path_length), in metres.
  double pathLength() const;

 private:
  std::vector<double> timestamps_;
  std::vector<SE3> poses_;
  bool hasTimestamps_ = true;
};

/// The pose (R(q), t) from a position and a quaternion, as evo builds poses from TUM/EuRoC rows: the quaternion
/// is normalised (transformations.quaternion_matrix: q·sqrt(2/|q|²), outer product). Throws InputError for a
/// quaternion of (near) zero norm, which names no rotation.
SE3 poseFromPositionQuaternion(const Vector3& t, double qw, double qx, double qy, double qz);

}  // namespace semslam
