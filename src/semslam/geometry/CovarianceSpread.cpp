#include "semslam/geometry/CovarianceSpread.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace semslam {

double largestStandardDeviation(const Matrix& covariance) {
  if (covariance.size() == 0) return 0.0;
  if (!covariance.allFinite()) return std::numeric_limits<double>::infinity();
  const Eigen::SelfAdjointEigenSolver<Matrix> solver(covariance, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(solver.eigenvalues().maxCoeff(), 0.0));
}

}  // namespace semslam
