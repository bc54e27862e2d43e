#include "semslam/io/TrajectoryTable.h"

#include "semslam/core/InputError.h"

namespace semslam {

Trajectory readTrajectoryTable(const std::string& path, const TrajectoryRowFormat& format) {
  const std::vector<NumericRow> rows = readNumericTable(path, format.separator);
  if (rows.empty()) throw InputError(path, 0, format.emptyFileProblem);
  const std::size_t firstRowFieldCount = rows.front().values.size();
  std::vector<double> stamps;
  std::vector<SE3> poses;
  stamps.reserve(rows.size());
  poses.reserve(rows.size());
  for (const NumericRow& row : rows) {
    const std::vector<double>& v = row.values;
    try {
      format.checkFields(v, firstRowFieldCount);
      const std::optional<double> stamp = format.timestamp(v);
      if (stamp && !stamps.empty() && *stamp < stamps.back()) {
        throw InputError("timestamp goes backwards (smaller than the previous line's)");
      }
      poses.push_back(format.pose(v));
      if (stamp) stamps.push_back(*stamp);
    } catch (const InputError& error) {
      throw InputError(path, row.line, error.problem());
    }
  }
  if (stamps.empty()) return Trajectory::withoutTimestamps(std::move(poses));
  return Trajectory(std::move(stamps), std::move(poses));
}

}  // namespace semslam
