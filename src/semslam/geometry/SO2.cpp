#include "semslam/geometry/SO2.h"

#include <ostream>
#include <stdexcept>

namespace semslam {

SO2 SO2::fromCosSin(double c, double s) {
  const double n = std::hypot(c, s);
  if (!(n > 0.0) || !std::isfinite(n)) {
    throw std::invalid_argument("SO2::fromCosSin: (c, s) must be finite and not both zero");
  }
  return SO2(c / n, s / n, Raw{});
}

std::ostream& operator<<(std::ostream& os, const SO2& R) { return os << "SO2(" << R.theta() << ")"; }

}  // namespace semslam
