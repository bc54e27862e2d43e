// largestStandardDeviation: √λmax of a covariance, against closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "semslam/geometry/CovarianceSpread.h"
#include "semslam/geometry/SO2.h"

using namespace semslam;

TEST(CovarianceSpread, IsTheLargestSigmaOfADiagonalCovariance) {
  EXPECT_DOUBLE_EQ(largestStandardDeviation(Vector3(0.04, 0.25, 0.01).asDiagonal().toDenseMatrix()), 0.5);
}

TEST(CovarianceSpread, DoesNotDependOnTheAxes) {
  // R diag(σ1², σ2²) Rᵀ has the same principal sigmas whatever the rotation.
  const Matrix2 rotation = SO2(0.7).matrix();
  const Matrix rotated = rotation * Vector2(0.09, 0.01).asDiagonal() * rotation.transpose();
  EXPECT_NEAR(largestStandardDeviation(rotated), 0.3, 1e-12);
}

TEST(CovarianceSpread, MatchesTheClosedFormOfATwoByTwoCovariance) {
  // λmax = (a + c)/2 + √(((a − c)/2)² + b²).
  const double a = 0.5, b = 0.2, c = 0.1;
  Matrix covariance(2, 2);
  covariance << a, b, b, c;
  const double largest = (a + c) / 2 + std::sqrt((a - c) * (a - c) / 4 + b * b);
  EXPECT_NEAR(largestStandardDeviation(covariance), std::sqrt(largest), 1e-12);
}

TEST(CovarianceSpread, EmptyNonFiniteAndRoundingCases) {
  EXPECT_EQ(largestStandardDeviation(Matrix(0, 0)), 0.0);
  Matrix nan = Matrix::Identity(2, 2);
  nan(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(largestStandardDeviation(nan), std::numeric_limits<double>::infinity());
  EXPECT_EQ(largestStandardDeviation(-1e-18 * Matrix::Identity(2, 2)), 0.0);  // negative by rounding: 0
}
