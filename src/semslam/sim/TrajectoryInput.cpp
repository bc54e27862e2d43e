#include "semslam/sim/TrajectoryInput.h"

#include <cmath>
#include <stdexcept>

#include "semslam/core/InputError.h"

namespace semslam {

namespace {

/// The body axes in camera coordinates: x forward = camera z, y left = −camera x, z up = −camera y.
SE3 cameraFromBody() {
  Matrix3 C;
  C << 0.0, -1.0, 0.0,  //
      0.0, 0.0, -1.0,   //
      1.0, 0.0, 0.0;
  return SE3(SO3(C), Point3::Zero());
}

}  // namespace

TrajectoryFrame parseTrajectoryFrame(const std::string& name) {
  if (name == "body") return TrajectoryFrame::Body;
  if (name == "camera") return TrajectoryFrame::Camera;
  throw std::invalid_argument("unknown trajectory frame '" + name + "' (expected one of: body, camera)");
}

SimTrajectory simTrajectoryFromFile(const Trajectory& trajectory, const TrajectoryInputOptions& options,
                                    const std::string& file) {
  if (options.dimension != 2 && options.dimension != 3) {
    throw std::invalid_argument("trajectory input: the dimension must be 2 or 3");
  }
  if (options.stride < 1) throw std::invalid_argument("trajectory input: the stride must be >= 1");
  if (options.maxSteps < 0) throw std::invalid_argument("trajectory input: the step limit must be >= 0");
  if (!std::isfinite(options.timeStep) || !(options.timeStep > 0.0)) {
    throw std::invalid_argument("trajectory input: the time step must be positive");
  }
  const SE3 C = cameraFromBody();
  const SE3 Cinverse = C.inverse();
  SimTrajectory result;
  for (std::size_t i = 0; i < trajectory.size(); i += static_cast<std::size_t>(options.stride)) {
    if (options.maxSteps > 0 && result.poses.size() > static_cast<std::size_t>(options.maxSteps)) break;
    const double time =
        trajectory.hasTimestamps() ? trajectory.timestamp(i) : static_cast<double>(i) * options.timeStep;
    if (!result.times.empty() && !(time > result.times.back())) continue;
    const SE3& read = trajectory.pose(i);
    SE3 pose(SO3::nearest(read.rotation().matrix()), read.translation());
    if (options.frame == TrajectoryFrame::Camera) pose = Cinverse.compose(pose).compose(C);
    result.times.push_back(time);
    if (options.dimension == 3) {
      result.poses.emplace_back(pose);
    } else {
      const Matrix3& R = pose.rotation().matrix();
      result.poses.emplace_back(SE2(pose.translation().x(), pose.translation().y(), std::atan2(R(1, 0), R(0, 0))));
    }
  }
  if (result.poses.size() < 2) {
    throw InputError(file, 0,
                     "the trajectory has " + std::to_string(result.poses.size()) +
                         " usable pose(s) (after the stride and dropping repeated times); a simulation needs two");
  }
  return result;
}

}  // namespace semslam
