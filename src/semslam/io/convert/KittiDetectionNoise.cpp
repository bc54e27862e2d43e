#include "semslam/io/convert/KittiDetectionNoise.h"

#include <cmath>
#include <stdexcept>

namespace semslam {

Matrix3 kittiDetectionCovariance(const Vector3& bodyPoint, const KittiRangeSigma& radial,
                                 const KittiRangeSigma& lateral) {
  const double range = bodyPoint.norm();
  if (!std::isfinite(range) || range <= 0.0) {
    throw std::invalid_argument("kittiDetectionCovariance: the detection must be a finite point other than the origin");
  }
  const Vector3 u = bodyPoint / range;
  const Matrix3 alongRay = u * u.transpose();
  const double sr = radial.at(range), sl = lateral.at(range);
  Matrix3 covariance = sr * sr * alongRay + sl * sl * (Matrix3::Identity() - alongRay);
  return 0.5 * (covariance + covariance.transpose());  // exactly symmetric
}

}  // namespace semslam
