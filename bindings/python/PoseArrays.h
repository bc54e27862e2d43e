#pragma once
// Poses ↔ numpy arrays, whole arrays at a time (the C++ loop fills the buffer; no per-element Python calls), and a
// log's step times:
//   N×3   planar poses, rows (x, y, θ)
//   N×7   spatial poses, rows (x, y, z, qx, qy, qz, qw) (TUM's order, Hamilton quaternion, w last)
//   N×4×4 homogeneous matrices

#include <pybind11/numpy.h>

#include <vector>

#include "semslam/geometry/SE3.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam::python {

namespace py = pybind11;

/// N×3 for planar poses, N×7 for spatial ones (all poses of one kind; an empty list gives 0×3).
py::array_t<double> poseArray(const std::vector<Pose>& poses);
/// N×7 rows (x, y, z, qx, qy, qz, qw).
py::array_t<double> xyzQuaternionArray(const std::vector<SE3>& poses);
/// N×4×4.
py::array_t<double> matrixArray(const std::vector<SE3>& poses);
/// The time of every step of `log`, in order (seconds).
Vector stepTimes(const MeasurementLog& log);

/// The inverse of the three forms above (planar rows become SE3 with z = 0 and a yaw rotation, as run folders
/// write them); anything else raises ValueError naming the shape.
std::vector<SE3> posesFromArray(const py::array_t<double>& array);

}  // namespace semslam::python
