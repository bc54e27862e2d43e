#include "semslam/models/Trajectory.h"

#include <cmath>
#include <string>

#include "semslam/core/InputError.h"

namespace semslam {

Trajectory::Trajectory(std::vector<double> timestamps, std::vector<SE3> poses, bool hasTimestamps)
    : timestamps_(std::move(timestamps)), poses_(std::move(poses)), hasTimestamps_(hasTimestamps) {
  if (timestamps_.size() != poses_.size()) {
    throw InputError("trajectory: " + std::to_string(timestamps_.size()) + " timestamps for " +
                     std::to_string(poses_.size()) + " poses");
  }
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    if (!std::isfinite(timestamps_[i]) || !poses_[i].rotation().matrix().allFinite() ||
        !poses_[i].translation().allFinite()) {
      throw InputError("trajectory: pose " + std::to_string(i) + " has a non-finite number");
    }
  }
}

Trajectory Trajectory::withoutTimestamps(std::vector<SE3> poses) {
  std::vector<double> indices(poses.size());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<double>(i);
  return Trajectory(std::move(indices), std::move(poses), false);
}

Eigen::Matrix3Xd Trajectory::positions() const {
  Eigen::Matrix3Xd result(3, static_cast<Eigen::Index>(poses_.size()));
  for (std::size_t i = 0; i < poses_.size(); ++i) result.col(static_cast<Eigen::Index>(i)) = position(i);
  return result;
}

Trajectory Trajectory::subset(const std::vector<std::size_t>& ids) const {
  Trajectory result;
  result.hasTimestamps_ = hasTimestamps_;
  result.timestamps_.reserve(ids.size());
  result.poses_.reserve(ids.size());
  for (const std::size_t id : ids) {
    result.timestamps_.push_back(timestamps_.at(id));
    result.poses_.push_back(poses_.at(id));
  }
  return result;
}

void Trajectory::transform(const SE3& a) {
  for (SE3& pose : poses_) pose = a * pose;
}

void Trajectory::scale(double s) {
  for (SE3& pose : poses_) pose = SE3(pose.rotation(), s * pose.translation());
}

double Trajectory::pathLength() const {
  double length = 0.0;
  for (std::size_t i = 1; i < poses_.size(); ++i) length += (position(i) - position(i - 1)).norm();
  return length;
}

SE3 poseFromPositionQuaternion(const Vector3& t, double qw, double qx, double qy, double qz) {
  const double n2 = qw * qw + qx * qx + qy * qy + qz * qz;
  if (!(n2 > 1e-12)) throw InputError("quaternion of zero norm names no rotation");
  const double k = std::sqrt(2.0 / n2);
  const double w = qw * k, x = qx * k, y = qy * k, z = qz * k;
  Matrix3 r;
  r << 1.0 - y * y - z * z, x * y - z * w, x * z + y * w,  //
      x * y + z * w, 1.0 - x * x - z * z, y * z - x * w,    //
      x * z - y * w, y * z + x * w, 1.0 - x * x - y * y;
  return SE3(SO3(r), t);
}

}  // namespace semslam
