#pragma once
// log N(x; mean, covariance), written out directly (Cholesky), as the closed form tests compare against.

#include <cmath>
#include <numbers>

#include <Eigen/Cholesky>

#include "semslam/geometry/Matrix.h"

namespace semslam::test {

inline double logGaussian(const Vector& x, const Vector& mean, const Matrix& covariance) {
  const Eigen::LLT<Matrix> llt(covariance);
  const Vector whitened = llt.matrixL().solve(x - mean);
  const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  return -0.5 * whitened.squaredNorm() - 0.5 * logDet - 0.5 * x.size() * std::log(2.0 * std::numbers::pi);
}

}  // namespace semslam::test
