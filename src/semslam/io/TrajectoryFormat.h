#pragma once
// The trajectory file formats semslam reads (for `semslam eval` and the simulators' input), by name: "tum", "kitti", "euroc" (see TumFormat.h,
// KittiFormat.h, EurocFormat.h for each layout).

#include <string>

#include "semslam/models/Trajectory.h"

namespace semslam {

enum class TrajectoryFormat { Tum, Kitti, Euroc };

/// "tum" | "kitti" | "euroc"; anything else throws InputError.
TrajectoryFormat parseTrajectoryFormat(const std::string& name);
std::string toString(TrajectoryFormat format);

/// Reads `path` in `format`; malformed input throws InputError(file, line, problem).
Trajectory readTrajectory(const std::string& path, TrajectoryFormat format);

}  // namespace semslam
