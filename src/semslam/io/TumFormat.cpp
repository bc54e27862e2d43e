#include "semslam/io/TumFormat.h"

#include <fstream>
#include <stdexcept>

#include "semslam/io/NumericTable.h"
#include "semslam/core/InputError.h"

namespace semslam {

Trajectory readTumTrajectory(const std::string& path) {
  const std::vector<NumericRow> rows = readNumericTable(path, Separator::Whitespace);
  if (rows.empty()) throw InputError(path, 0, "no poses (empty TUM trajectory file)");
  std::vector<double> stamps;
  std::vector<SE3> poses;
  stamps.reserve(rows.size());
  poses.reserve(rows.size());
  for (const NumericRow& row : rows) {
    const std::vector<double>& v = row.values;
    if (v.size() != 8) {
      throw InputError(path, row.line,
                       "expected 8 numbers (timestamp tx ty tz qx qy qz qw), found " + std::to_string(v.size()));
    }
    if (!stamps.empty() && v[0] < stamps.back()) {
      throw InputError(path, row.line, "timestamp goes backwards (smaller than the previous line's)");
    }
    try {
      poses.push_back(poseFromPositionQuaternion(Vector3(v[1], v[2], v[3]), v[7], v[4], v[5], v[6]));
    } catch (const InputError& error) {
      throw InputError(path, row.line, error.problem());
    }
    stamps.push_back(v[0]);
  }
  return Trajectory(std::move(stamps), std::move(poses));
}

void writeTumTrajectory(const std::string& path, const Trajectory& trajectory) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Vector3& t = trajectory.position(i);
    const Eigen::Quaterniond q = trajectory.pose(i).rotation().toQuaternion();
    out << formatNumber(trajectory.timestamp(i)) << ' ' << formatNumber(t.x()) << ' ' << formatNumber(t.y()) << ' '
        << formatNumber(t.z()) << ' ' << formatNumber(q.x()) << ' ' << formatNumber(q.y()) << ' '
        << formatNumber(q.z()) << ' ' << formatNumber(q.w()) << '\n';
  }
  if (!out) throw std::runtime_error("error writing " + path);
}

}  // namespace semslam
