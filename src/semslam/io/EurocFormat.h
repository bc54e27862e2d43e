#pragma once
// EuRoC MAV ground truth (Burri et al. 2016), `<seq>/mav0/state_groundtruth_estimate0/data.csv`, read as evo's
// file_interface.read_euroc_csv_trajectory does:
//   comma-separated, `timestamp[ns], p_x, p_y, p_z, q_w, q_x, q_y, q_z, ...` (quaternion with w FIRST), any further
//   columns (velocity, biases) ignored; lines starting with '#' (the header) are comments.
// Timestamps are nanoseconds, converted to seconds as evo does: the integer read as a double, divided by 1e9.
// The quaternion is normalised; a zero quaternion is an error.
//
// Malformed input throws InputError(file, line, problem): fewer than 8 fields, a different field count than the
// first data line, a non-finite or non-numeric field, a zero quaternion, a timestamp smaller than the previous one,
// or a file with no pose at all. (An EuRoC *estimate* is usually a TUM file: read it with readTumTrajectory.)

#include <string>

#include "semslam/models/Trajectory.h"

namespace semslam {

Trajectory readEurocTrajectory(const std::string& path);

}  // namespace semslam
