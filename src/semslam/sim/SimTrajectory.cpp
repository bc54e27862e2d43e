#include "semslam/sim/SimTrajectory.h"

namespace semslam {

int SimTrajectory::dimension() const {
  if (poses.empty()) return 2;
  return std::holds_alternative<SE3>(poses.front()) ? 3 : 2;
}

}  // namespace semslam
