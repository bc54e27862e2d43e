#pragma once
// SimTrajectory: the true poses a simulator moves the robot along, with their times, in the measurement log's
// conventions: SE2 poses for dimension 2, SE3 for dimension 3, robot (body) frame x forward, y left, z up.
// GeneratedPath.h makes one; TrajectoryInput.h converts one read from a TUM or KITTI file.

#include <vector>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

struct SimTrajectory {
  std::vector<double> times;  // seconds, strictly increasing
  std::vector<Pose> poses;    // all SE2 or all SE3
  int dimension() const;      // 2 or 3 (from the first pose; 2 when empty)
};

}  // namespace semslam
