#include "semslam/io/TrajectoryFormat.h"

#include "semslam/io/EurocFormat.h"
#include "semslam/io/KittiFormat.h"
#include "semslam/io/TumFormat.h"
#include "semslam/core/InputError.h"

namespace semslam {

TrajectoryFormat parseTrajectoryFormat(const std::string& name) {
  if (name == "tum") return TrajectoryFormat::Tum;
  if (name == "kitti") return TrajectoryFormat::Kitti;
  if (name == "euroc") return TrajectoryFormat::Euroc;
  throw InputError("unknown trajectory format '" + name + "' (expected tum, kitti or euroc)");
}

std::string toString(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::Tum: return "tum";
    case TrajectoryFormat::Kitti: return "kitti";
    case TrajectoryFormat::Euroc: return "euroc";
  }
  return "unknown";
}

Trajectory readTrajectory(const std::string& path, TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::Tum: return readTumTrajectory(path);
    case TrajectoryFormat::Kitti: return readKittiTrajectory(path);
    case TrajectoryFormat::Euroc: return readEurocTrajectory(path);
  }
  throw InputError("unknown trajectory format");
}

}  // namespace semslam
