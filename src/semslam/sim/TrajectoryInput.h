#pragma once
// TrajectoryInput: a trajectory read from a file (io's TUM or KITTI reader) made into a simulator's truth.
//
//   frame    KITTI poses are camera poses (x right, y down, z forward) in the first camera's frame; the
//            simulators' sensors look along the body's x axis with z up. TrajectoryFrame::Camera re-expresses
//            every pose T_i as C⁻¹ T_i C with C = [[0, −1, 0], [0, 0, −1], [1, 0, 0]] (the body axes x forward =
//            camera z, y left = −camera x, z up = −camera y): body poses in a z-up world. Body leaves the poses
//            as they are (TUM files usually hold body poses in a z-up world already). The CLI's default is
//            camera for kitti and body for tum.
//   rotation the rotation blocks are projected onto SO(3) (SO3::nearest): KITTI rounds them to 7-9 digits, and
//            the log's unit quaternions need a proper rotation.
//   stride   every stride-th pose is kept (0, stride, 2·stride, ...).
//   times    the file's timestamps where it has them, else index · timeStep (the index in the file); a pose
//            whose time is not after the previous kept one is skipped (TUM files may repeat a stamp; the log
//            needs strictly increasing times).
//   steps    at most maxSteps steps after the first pose (0: all).
//   2D       SE2(x, y, yaw), yaw = atan2(R₁₀, R₀₀) (the heading of the body x axis in the xy-plane).
// Fewer than two poses left is an InputError naming the file.

#include <string>

#include "semslam/models/Trajectory.h"
#include "semslam/sim/SimTrajectory.h"

namespace semslam {

enum class TrajectoryFrame { Body, Camera };

/// "body" | "camera"; anything else throws std::invalid_argument.
TrajectoryFrame parseTrajectoryFrame(const std::string& name);

struct TrajectoryInputOptions {
  int dimension = 3;
  TrajectoryFrame frame = TrajectoryFrame::Body;
  int stride = 1;
  int maxSteps = 0;  // 0: all
  double timeStep = 0.1;
};

/// `file` names the source in messages. Throws InputError for fewer than two usable poses and
/// std::invalid_argument for invalid options.
SimTrajectory simTrajectoryFromFile(const Trajectory& trajectory, const TrajectoryInputOptions& options,
                                    const std::string& file);

}  // namespace semslam
