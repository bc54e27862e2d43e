#include "semslam/io/KittiFormat.h"

#include <fstream>
#include <stdexcept>

#include <Eigen/LU>

#include "semslam/io/NumericTable.h"
#include "semslam/core/InputError.h"

namespace semslam {

namespace {

constexpr double kRotationTolerance = 1e-3;

bool isRotation(const Matrix3& r) {
  return (r.transpose() * r - Matrix3::Identity()).cwiseAbs().maxCoeff() <= kRotationTolerance && r.determinant() > 0.0;
}

}  // namespace

Trajectory readKittiTrajectory(const std::string& path) {
  const std::vector<NumericRow> rows = readNumericTable(path, Separator::Whitespace);
  if (rows.empty()) throw InputError(path, 0, "no poses (empty KITTI pose file)");
  const std::size_t columns = rows.front().values.size();
  if (columns != 12 && columns != 13) {
    throw InputError(path, rows.front().line,
                     "expected 12 numbers (row-major 3x4 pose) or 13 (timestamp first), found " +
                         std::to_string(columns));
  }
  const bool timed = columns == 13;
  std::vector<double> stamps;
  std::vector<SE3> poses;
  stamps.reserve(rows.size());
  poses.reserve(rows.size());
  for (const NumericRow& row : rows) {
    const std::vector<double>& v = row.values;
    if (v.size() != columns) {
      throw InputError(path, row.line,
                       "expected " + std::to_string(columns) + " numbers like the first pose line, found " +
                           std::to_string(v.size()));
    }
    const std::size_t first = timed ? 1 : 0;
    Matrix3 rotation;
    Vector3 translation;
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t c = 0; c < 3; ++c) rotation(static_cast<int>(r), static_cast<int>(c)) = v[first + 4 * r + c];
      translation(static_cast<int>(r)) = v[first + 4 * r + 3];
    }
    if (!isRotation(rotation)) {
      throw InputError(path, row.line, "the 3x3 block is not a rotation matrix (tolerance 1e-3)");
    }
    if (timed) {
      if (!stamps.empty() && v[0] < stamps.back()) {
        throw InputError(path, row.line, "timestamp goes backwards (smaller than the previous line's)");
      }
      stamps.push_back(v[0]);
    }
    poses.push_back(SE3(SO3(rotation), translation));
  }
  if (!timed) return Trajectory::withoutTimestamps(std::move(poses));
  return Trajectory(std::move(stamps), std::move(poses));
}

void writeKittiTrajectory(const std::string& path, const Trajectory& trajectory, bool withTimestamps) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  const bool timed = withTimestamps && trajectory.hasTimestamps();
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Matrix4 pose = trajectory.pose(i).matrix();
    if (timed) out << formatNumber(trajectory.timestamp(i)) << ' ';
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) out << formatNumber(pose(r, c)) << (r == 2 && c == 3 ? '\n' : ' ');
    }
  }
  if (!out) throw std::runtime_error("error writing " + path);
}

}  // namespace semslam
