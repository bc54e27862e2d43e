#include "semslam/graph/RobustKernel.h"

#include <cmath>
#include <stdexcept>

namespace semslam {

HuberKernel::HuberKernel(double threshold) : threshold_(threshold) {
  if (!(threshold > 0.0) || !std::isfinite(threshold)) throw std::invalid_argument("Huber threshold must be > 0");
}

double HuberKernel::cost(double squaredError) const {
  const double k2 = threshold_ * threshold_;
  return squaredError <= k2 ? squaredError : 2.0 * threshold_ * std::sqrt(squaredError) - k2;
}

double HuberKernel::weight(double squaredError) const {
  return squaredError <= threshold_ * threshold_ ? 1.0 : threshold_ / std::sqrt(squaredError);
}

CauchyKernel::CauchyKernel(double scale) : scale_(scale) {
  if (!(scale > 0.0) || !std::isfinite(scale)) throw std::invalid_argument("Cauchy scale must be > 0");
}

double CauchyKernel::cost(double squaredError) const {
  const double k2 = scale_ * scale_;
  return k2 * std::log1p(squaredError / k2);
}

double CauchyKernel::weight(double squaredError) const { return 1.0 / (1.0 + squaredError / (scale_ * scale_)); }

}  // namespace semslam
