#include "semslam/io/EurocFormat.h"

#include "semslam/io/NumericTable.h"
#include "semslam/core/InputError.h"

namespace semslam {

Trajectory readEurocTrajectory(const std::string& path) {
  const std::vector<NumericRow> rows = readNumericTable(path, Separator::Comma);
  if (rows.empty()) throw InputError(path, 0, "no poses (empty EuRoC ground-truth file)");
  const std::size_t columns = rows.front().values.size();
  std::vector<double> stamps;
  std::vector<SE3> poses;
  stamps.reserve(rows.size());
  poses.reserve(rows.size());
  for (const NumericRow& row : rows) {
    const std::vector<double>& v = row.values;
    if (v.size() < 8) {
      throw InputError(path, row.line,
                       "expected at least 8 fields (timestamp[ns], px, py, pz, qw, qx, qy, qz), found " +
                           std::to_string(v.size()));
    }
    if (v.size() != columns) {
      throw InputError(path, row.line,
                       "expected " + std::to_string(columns) + " fields like the first data line, found " +
                           std::to_string(v.size()));
    }
    const double stamp = v[0] / 1e9;
    if (!stamps.empty() && stamp < stamps.back()) {
      throw InputError(path, row.line, "timestamp goes backwards (smaller than the previous line's)");
    }
    try {
      poses.push_back(poseFromPositionQuaternion(Vector3(v[1], v[2], v[3]), v[4], v[5], v[6], v[7]));
    } catch (const InputError& error) {
      throw InputError(path, row.line, error.problem());
    }
    stamps.push_back(stamp);
  }
  return Trajectory(std::move(stamps), std::move(poses));
}

}  // namespace semslam
