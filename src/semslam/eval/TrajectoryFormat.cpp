#include "semslam/eval/TrajectoryFormat.h"

#include "semslam/eval/EurocFormat.h"
#include "semslam/eval/KittiFormat.h"
#include "semslam/eval/TumFormat.h"
#include "semslam/io/InputError.h"

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
