#include "semslam/io/TumFormat.h"

#include <fstream>
#include <stdexcept>

#include "semslam/io/TrajectoryTable.h"
#include "semslam/core/ExactNumber.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/core/InputError.h"

namespace semslam {

Trajectory readTumTrajectory(const std::string& path) {
  TrajectoryRowFormat tum;
  tum.separator = Separator::Whitespace;
  tum.emptyFileProblem = "no poses (empty TUM trajectory file)";
  tum.checkFields = [](const std::vector<double>& v, std::size_t) {
    if (v.size() != 8) {
      throw InputError("expected 8 numbers (timestamp tx ty tz qx qy qz qw), found " + std::to_string(v.size()));
    }
  };
  tum.timestamp = [](const std::vector<double>& v) { return std::optional<double>(v[0]); };
  tum.pose = [](const std::vector<double>& v) {
    return poseFromPositionQuaternion(Vector3(v[1], v[2], v[3]), v[7], v[4], v[5], v[6]);
  };
  return readTrajectoryTable(path, tum);
}

void writeTumTrajectory(const std::string& path, const Trajectory& trajectory) {
  writeFileAtomically(path, [&](std::ostream& out) {
    for (std::size_t i = 0; i < trajectory.size(); ++i) {
      const Vector3& t = trajectory.position(i);
      const Eigen::Quaterniond q = trajectory.pose(i).rotation().toQuaternion();
      out << shortestExactNumber(trajectory.timestamp(i)) << ' ' << shortestExactNumber(t.x()) << ' ' << shortestExactNumber(t.y()) << ' '
          << shortestExactNumber(t.z()) << ' ' << shortestExactNumber(q.x()) << ' ' << shortestExactNumber(q.y()) << ' '
          << shortestExactNumber(q.z()) << ' ' << shortestExactNumber(q.w()) << '\n';
    }
  });
}

}  // namespace semslam
