#include "PoseArrays.h"

#include <stdexcept>
#include <string>

#include "semslam/io/RunFolder.h"
#include "semslam/models/Trajectory.h"

namespace semslam::python {

py::array_t<double> poseArray(const std::vector<Pose>& poses) {
  const bool spatial = !poses.empty() && std::holds_alternative<SE3>(poses.front());
  if (spatial) {
    std::vector<SE3> spatialPoses;
    spatialPoses.reserve(poses.size());
    for (const Pose& pose : poses) spatialPoses.push_back(std::get<SE3>(pose));
    return xyzQuaternionArray(spatialPoses);
  }
  py::array_t<double> array({static_cast<py::ssize_t>(poses.size()), py::ssize_t{3}});
  auto rows = array.mutable_unchecked<2>();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const SE2& pose = std::get<SE2>(poses[i]);
    rows(i, 0) = pose.x();
    rows(i, 1) = pose.y();
    rows(i, 2) = pose.theta();
  }
  return array;
}

Vector stepTimes(const MeasurementLog& log) {
  Vector times(static_cast<Eigen::Index>(log.steps.size()));
  for (std::size_t k = 0; k < log.steps.size(); ++k) times(static_cast<Eigen::Index>(k)) = log.steps[k].time;
  return times;
}

py::array_t<double> xyzQuaternionArray(const std::vector<SE3>& poses) {
  py::array_t<double> array({static_cast<py::ssize_t>(poses.size()), py::ssize_t{7}});
  auto rows = array.mutable_unchecked<2>();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Point3& t = poses[i].translation();
    const Eigen::Quaterniond q = poses[i].rotation().toQuaternion();
    const double row[7] = {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()};
    for (int j = 0; j < 7; ++j) rows(i, j) = row[j];
  }
  return array;
}

py::array_t<double> matrixArray(const std::vector<SE3>& poses) {
  py::array_t<double> array({static_cast<py::ssize_t>(poses.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto cells = array.mutable_unchecked<3>();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Matrix4d T = poses[i].matrix();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) cells(i, r, c) = T(r, c);
  }
  return array;
}

std::vector<SE3> posesFromArray(const py::array_t<double>& input) {
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(input);
  if (!array) throw std::invalid_argument("poses: not an array of numbers");
  std::string shape;
  for (py::ssize_t d = 0; d < array.ndim(); ++d) shape += (d ? "×" : "") + std::to_string(array.shape(d));
  std::vector<SE3> poses;
  if (array.ndim() == 2 && array.shape(1) == 3) {
    auto rows = array.unchecked<2>();
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) poses.push_back(toSE3(SE2(rows(i, 0), rows(i, 1), rows(i, 2))));
  } else if (array.ndim() == 2 && array.shape(1) == 7) {
    auto rows = array.unchecked<2>();
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
      poses.push_back(poseFromPositionQuaternion(Vector3(rows(i, 0), rows(i, 1), rows(i, 2)), rows(i, 6), rows(i, 3),
                                                 rows(i, 4), rows(i, 5)));
    }
  } else if (array.ndim() == 3 && array.shape(1) == 4 && array.shape(2) == 4) {
    auto cells = array.unchecked<3>();
    for (py::ssize_t i = 0; i < cells.shape(0); ++i) {
      Eigen::Matrix3d R;
      Eigen::Vector3d t;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) R(r, c) = cells(i, r, c);
        t(r) = cells(i, r, 3);
      }
      poses.push_back(SE3(SO3(R), t));  // kept as given, as the trajectory readers keep rotations (Trajectory.h)
    }
  } else {
    throw std::invalid_argument("poses: expected N×3 (x, y, θ), N×7 (x, y, z, qx, qy, qz, qw) or N×4×4, got " +
                                (shape.empty() ? std::string("a scalar") : shape));
  }
  return poses;
}

}  // namespace semslam::python
