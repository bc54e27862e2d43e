#include "semslam/io/EurocFormat.h"

#include "semslam/io/TrajectoryTable.h"
#include "semslam/core/InputError.h"

namespace semslam {

Trajectory readEurocTrajectory(const std::string& path) {
  TrajectoryRowFormat euroc;
  euroc.separator = Separator::Comma;
  euroc.emptyFileProblem = "no poses (empty EuRoC ground-truth file)";
  euroc.checkFields = [](const std::vector<double>& v, std::size_t columns) {
    if (v.size() < 8) {
      throw InputError("expected at least 8 fields (timestamp[ns], px, py, pz, qw, qx, qy, qz), found " +
                       std::to_string(v.size()));
    }
    if (v.size() != columns) {
      throw InputError("expected " + std::to_string(columns) + " fields like the first data line, found " +
                       std::to_string(v.size()));
    }
  };
  euroc.timestamp = [](const std::vector<double>& v) { return std::optional<double>(v[0] / 1e9); };
  euroc.pose = [](const std::vector<double>& v) {
    return poseFromPositionQuaternion(Vector3(v[1], v[2], v[3]), v[4], v[5], v[6], v[7]);
  };
  return readTrajectoryTable(path, euroc);
}

}  // namespace semslam
