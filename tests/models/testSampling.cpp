// Sampling helpers: uniform01 range and moments, Gaussian draws with full and rank-deficient covariances, and
// determinism for a seed.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "semslam/models/Sampling.h"

namespace semslam {
namespace {

TEST(Sampling, UniformIsInTheUnitIntervalWithTheRightMoments) {
  std::mt19937 rng(71);
  const int n = 200000;
  double sum = 0.0, sumSquares = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = uniform01(rng);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sumSquares += u * u;
  }
  EXPECT_NEAR(sum / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(sumSquares / n - (sum / n) * (sum / n), 1.0 / 12.0, 2e-3);
}

TEST(Sampling, GaussianDrawsHaveTheRequestedMoments) {
  std::mt19937 rng(72);
  Matrix S(3, 3);
  S << 2.0, 0.6, -0.3, 0.6, 1.0, 0.2, -0.3, 0.2, 0.5;
  const Vector mean = Vector3(1.0, -2.0, 0.5);
  const int n = 200000;
  Vector sum = Vector::Zero(3);
  Matrix outer = Matrix::Zero(3, 3);
  for (int i = 0; i < n; ++i) {
    const Vector x = sampleGaussian(mean, S, rng);
    sum += x;
    outer += (x - mean) * (x - mean).transpose();
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(sum(i) / n, mean(i), 5.0 * std::sqrt(S(i, i) / n));
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(outer(i, j) / n, S(i, j), 5.0 * std::sqrt((S(i, i) * S(j, j) + S(i, j) * S(i, j)) / n));
    }
  }
}

TEST(Sampling, RankDeficientCovarianceStaysInItsSubspace) {
  std::mt19937 rng(73);
  const Vector3 direction = Vector3(1.0, 2.0, -1.0).normalized();
  const Matrix S = 0.3 * direction * direction.transpose();  // rank 1: LLT fails, the eigen path is used
  double sumSquares = 0.0;
  const int n = 50000;
  for (int i = 0; i < n; ++i) {
    const Vector x = sampleGaussian(Vector::Zero(3), S, rng);
    EXPECT_LT((x - direction * direction.dot(x)).norm(), 1e-7);
    sumSquares += direction.dot(x) * direction.dot(x);
  }
  EXPECT_NEAR(sumSquares / n, 0.3, 5.0 * 0.3 * std::sqrt(2.0 / n));
  EXPECT_THROW(sampleGaussian(Vector::Zero(2), -Matrix::Identity(2, 2), rng), std::invalid_argument);
  EXPECT_THROW(sampleGaussian(Vector::Zero(2), Matrix::Identity(3, 3), rng), std::invalid_argument);
}

TEST(Sampling, PairedNormalsAreIndependentStandardNormals) {
  // Two rows: row 0 holds the cosine and row 1 the sine of each pair (storage order, column by column), so the
  // correlation of the rows is that of the pair's two normals: zero for independent draws.
  std::mt19937 rng(74);
  const int n = 200000;
  const Matrix draws = standardNormalMatrix(2, n, rng);
  double mean0 = draws.row(0).mean(), mean1 = draws.row(1).mean();
  const double variance0 = (draws.row(0).array() - mean0).square().mean();
  const double variance1 = (draws.row(1).array() - mean1).square().mean();
  const double covariance = ((draws.row(0).array() - mean0) * (draws.row(1).array() - mean1)).mean();
  const double fourthMoment = draws.row(1).array().pow(4).mean();  // 3 for a normal
  EXPECT_NEAR(mean0, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(mean1, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(variance0, 1.0, 5.0 * std::sqrt(2.0 / n));
  EXPECT_NEAR(variance1, 1.0, 5.0 * std::sqrt(2.0 / n));
  EXPECT_NEAR(covariance, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(fourthMoment, 3.0, 5.0 * std::sqrt(96.0 / n));
}

TEST(Sampling, PairedNormalsConsumeFourOutputsPerPair) {
  std::mt19937 odd(9), reference(9);
  const Matrix draws = standardNormalMatrix(3, 1, odd);  // two pairs, the last sine discarded
  reference.discard(8);
  EXPECT_EQ(odd(), reference());
  std::mt19937 again(9);
  EXPECT_EQ(standardNormalMatrix(3, 1, again), draws);
  EXPECT_THROW(standardNormalMatrix(-1, 2, again), std::invalid_argument);
}

TEST(Sampling, ASeedRepeatsItsDraws) {
  std::mt19937 a(5), b(5);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(standardNormal(a), standardNormal(b));
  EXPECT_EQ(sampleGaussian(Vector::Zero(4), Matrix::Identity(4, 4), a),
            sampleGaussian(Vector::Zero(4), Matrix::Identity(4, 4), b));
}

}  // namespace
}  // namespace semslam
