#include "semslam/io/KittiFormat.h"

#include <fstream>
#include <stdexcept>

#include <Eigen/LU>

#include "semslam/io/TrajectoryTable.h"
#include "semslam/core/ExactNumber.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/core/InputError.h"

namespace semslam {

namespace {

constexpr double kRotationTolerance = 1e-3;

bool isRotation(const Matrix3& r) {
  return (r.transpose() * r - Matrix3::Identity()).cwiseAbs().maxCoeff() <= kRotationTolerance && r.determinant() > 0.0;
}

/// 13 numbers: a timestamp, then the pose; 12: the pose alone.
bool isTimed(const std::vector<double>& v) { return v.size() == 13; }

/// The row-major 3x4 pose [R | t] of a row, after its timestamp if it has one.
void poseBlocks(const std::vector<double>& v, Matrix3& rotation, Vector3& translation) {
  const std::size_t first = isTimed(v) ? 1 : 0;
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) rotation(static_cast<int>(r), static_cast<int>(c)) = v[first + 4 * r + c];
    translation(static_cast<int>(r)) = v[first + 4 * r + 3];
  }
}

}  // namespace

Trajectory readKittiTrajectory(const std::string& path) {
  TrajectoryRowFormat kitti;
  kitti.separator = Separator::Whitespace;
  kitti.emptyFileProblem = "no poses (empty KITTI pose file)";
  kitti.checkFields = [](const std::vector<double>& v, std::size_t columns) {
    if (columns != 12 && columns != 13) {  // only ever true on the first row, which sets `columns`
      throw InputError("expected 12 numbers (row-major 3x4 pose) or 13 (timestamp first), found " +
                       std::to_string(columns));
    }
    if (v.size() != columns) {
      throw InputError("expected " + std::to_string(columns) + " numbers like the first pose line, found " +
                       std::to_string(v.size()));
    }
    Matrix3 rotation;
    Vector3 translation;
    poseBlocks(v, rotation, translation);
    if (!isRotation(rotation)) throw InputError("the 3x3 block is not a rotation matrix (tolerance 1e-3)");
  };
  kitti.timestamp = [](const std::vector<double>& v) {
    return isTimed(v) ? std::optional<double>(v[0]) : std::nullopt;
  };
  kitti.pose = [](const std::vector<double>& v) {
    Matrix3 rotation;
    Vector3 translation;
    poseBlocks(v, rotation, translation);
    return SE3(SO3(rotation), translation);
  };
  return readTrajectoryTable(path, kitti);
}

void writeKittiTrajectory(const std::string& path, const Trajectory& trajectory, bool withTimestamps) {
  writeFileAtomically(path, [&](std::ostream& out) {
    const bool timed = withTimestamps && trajectory.hasTimestamps();
    for (std::size_t i = 0; i < trajectory.size(); ++i) {
      const Matrix4 pose = trajectory.pose(i).matrix();
      if (timed) out << shortestExactNumber(trajectory.timestamp(i)) << ' ';
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) out << shortestExactNumber(pose(r, c)) << (r == 2 && c == 3 ? '\n' : ' ');
      }
    }
  });
}

}  // namespace semslam
