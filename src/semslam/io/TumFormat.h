#pragma once
// TUM RGB-D trajectory files (Sturm et al. 2012; evo's file_interface.read_tum_trajectory_file):
//   one pose per line, `timestamp tx ty tz qx qy qz qw` (seconds, metres, Hamilton quaternion with w LAST),
//   separated by spaces or tabs; lines starting with '#' are comments.
// The quaternion is normalised (as evo does); a zero quaternion is an error.
//
// Malformed input throws InputError(file, line, problem): a line without exactly 8 numbers, a field that is not
// a finite number, a zero quaternion, a timestamp smaller than the one before it, or a file with no pose at all.
// Equal consecutive timestamps are accepted: real benchmark files have them (fr2_desk groundtruth, EuRoC
// V1_02 estimates), evo reads them, and association then takes the first of the equal stamps.

#include <string>

#include "semslam/models/Trajectory.h"

namespace semslam {

Trajectory readTumTrajectory(const std::string& path);

/// Writes `t x y z qx qy qz qw` lines, numbers in shortest round-trip form. Throws std::runtime_error when the
/// file cannot be written.
void writeTumTrajectory(const std::string& path, const Trajectory& trajectory);

}  // namespace semslam
