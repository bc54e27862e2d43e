#pragma once
// The one row loop of the trajectory readers (TUM, KITTI, EuRoC): a numeric table (NumericTable.h) of one pose per
// line, each format supplying only how to read a row.
//
// For every row, in this order:
//   1. checkFields(values, firstRowFieldCount)  throws InputError(problem) when the row cannot be a pose line;
//   2. timestamp(values)                        the row's time [s], or nullopt when the format has none;
//   3. a timestamp smaller than the previous row's is an error (equal ones are allowed);
//   4. pose(values)                             the pose; may throw InputError(problem).
// Every InputError a step throws is reported at (path, row line) with its problem. An empty table is an error at
// line 0 with `emptyFileProblem`. The result has timestamps exactly when the rows have them.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "semslam/io/NumericTable.h"
#include "semslam/models/Trajectory.h"

namespace semslam {

struct TrajectoryRowFormat {
  Separator separator = Separator::Whitespace;
  std::string emptyFileProblem;
  std::function<void(const std::vector<double>& values, std::size_t firstRowFieldCount)> checkFields;
  std::function<std::optional<double>(const std::vector<double>& values)> timestamp;
  std::function<SE3(const std::vector<double>& values)> pose;
};

/// Reads the trajectory in `path`, one pose per row, as `format` says.
Trajectory readTrajectoryTable(const std::string& path, const TrajectoryRowFormat& format);

}  // namespace semslam
