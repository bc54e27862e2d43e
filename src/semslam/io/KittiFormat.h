#pragma once
// KITTI odometry pose files (Geiger et al.; evo's file_interface.read_kitti_poses_file):
//   one pose per line, the first three rows of the 4x4 pose matrix, row-major: `r11 r12 r13 tx r21 ... r33 tz`.
// KITTI files carry no time: such a trajectory has hasTimestamps() false and uses the index as time.
// Also accepted (not by evo): a leading timestamp column, 13 numbers per line, as the KITTI ground truth with
// times (`../shared/data/kitti-odometry-poses/*.txt`) has; then the times are real timestamps in seconds.
// Separators are spaces or tabs; lines starting with '#' are comments.
//
// The rotation block is used exactly as written (KITTI rounds it to 7-9 digits and evo does not re-orthonormalise
// it either); it is only checked to be a rotation to 1e-3 (|RᵀR - I| and det R > 0), to catch misread files.
//
// Malformed input throws InputError(file, line, problem): a line with neither 12 nor 13 numbers or with a different
// count than the first data line, a non-finite or non-numeric field, a block that is no rotation, a timestamp
// smaller than the previous one (13 columns), or a file with no pose at all.

#include <string>

#include "semslam/models/Trajectory.h"

namespace semslam {

Trajectory readKittiTrajectory(const std::string& path);

/// Writes 12 numbers per line, or 13 with the timestamp first when `withTimestamps` (and the trajectory has
/// timestamps). Throws std::runtime_error when the file cannot be written.
void writeKittiTrajectory(const std::string& path, const Trajectory& trajectory, bool withTimestamps = false);

}  // namespace semslam
