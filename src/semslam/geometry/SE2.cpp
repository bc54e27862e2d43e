#include "semslam/geometry/SE2.h"

#include <ostream>

namespace semslam {

std::ostream& operator<<(std::ostream& os, const SE2& T) {
  return os << "SE2(" << T.x() << ", " << T.y() << ", " << T.theta() << ")";
}

}  // namespace semslam
