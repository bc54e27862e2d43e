#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <numbers>

#include "semslam/graph/NoiseModel.h"
#include "semslam/graph/RobustKernel.h"

using namespace semslam;

namespace {

Matrix randomCovariance(int d, unsigned seed) {
  std::srand(seed);
  const Matrix a = Matrix::Random(d, d);
  return a * a.transpose() + 0.5 * Matrix::Identity(d, d);
}

}  // namespace

TEST(NoiseModel, CovarianceInformationAndSqrtInformationAgree) {
  const Matrix covariance = randomCovariance(3, 7);
  const SharedNoiseModel fromCovariance = NoiseModel::fromCovariance(covariance);
  const SharedNoiseModel fromInformation = NoiseModel::fromInformation(covariance.inverse());
  const Matrix R = fromCovariance->sqrtInformation();
  EXPECT_TRUE(R.isUpperTriangular(0.0));
  EXPECT_TRUE((R.transpose() * R).isApprox(covariance.inverse(), 1e-12));
  EXPECT_TRUE(fromInformation->sqrtInformation().isApprox(R, 1e-12));
  EXPECT_TRUE(fromCovariance->covariance().isApprox(covariance, 1e-12));
  EXPECT_TRUE(NoiseModel::fromSqrtInformation(R)->information().isApprox(covariance.inverse(), 1e-12));
  EXPECT_FALSE(fromCovariance->isDiagonal());
}

TEST(NoiseModel, WhitenedSquaredNormIsMahalanobisDistance) {
  const Matrix covariance = randomCovariance(4, 3);
  const Vector e = Vector::Random(4);
  const SharedNoiseModel model = NoiseModel::fromCovariance(covariance);
  EXPECT_NEAR(model->whiten(e).squaredNorm(), e.dot(covariance.inverse() * e), 1e-10);
  Matrix jacobian = Matrix::Random(4, 2);
  const Matrix expected = model->sqrtInformation() * jacobian;
  model->whitenInPlace(jacobian);
  EXPECT_TRUE(jacobian.isApprox(expected, 1e-14));
}

TEST(NoiseModel, DiagonalModels) {
  const SharedNoiseModel model = NoiseModel::fromSigmas(Vector3(0.1, 2.0, 0.5));
  EXPECT_TRUE(model->isDiagonal());
  EXPECT_TRUE(model->whiten(Vector3(1.0, 1.0, 1.0)).isApprox(Vector3(10.0, 0.5, 2.0)));
  const SharedNoiseModel isotropic = NoiseModel::isotropic(2, 0.25);
  EXPECT_TRUE(isotropic->covariance().isApprox(0.0625 * Matrix::Identity(2, 2)));
}

TEST(NoiseModel, LogNormalizerIsTheGaussianConstant) {
  const Matrix covariance = randomCovariance(3, 11);
  const double expected = 0.5 * 3 * std::log(2.0 * std::numbers::pi) + 0.5 * std::log(covariance.determinant());
  EXPECT_NEAR(NoiseModel::fromCovariance(covariance)->logNormalizer(), expected, 1e-12);
}

TEST(NoiseModel, SqrtInformationWithNegativeDiagonalIsNormalised) {
  Matrix R(2, 2);
  R << -2.0, 1.0, 0.0, 3.0;
  const SharedNoiseModel model = NoiseModel::fromSqrtInformation(R);
  EXPECT_GT(model->sqrtInformation()(0, 0), 0.0);
  EXPECT_TRUE(model->information().isApprox(R.transpose() * R));
}

TEST(NoiseModel, RejectsInvalidMatrices) {
  Matrix notPositive(2, 2);
  notPositive << 1.0, 2.0, 2.0, 1.0;
  EXPECT_THROW(NoiseModel::fromCovariance(notPositive), std::invalid_argument);
  EXPECT_THROW(NoiseModel::fromInformation(notPositive), std::invalid_argument);
  Matrix notSymmetric(2, 2);
  notSymmetric << 1.0, 0.5, 0.0, 1.0;
  EXPECT_THROW(NoiseModel::fromInformation(notSymmetric), std::invalid_argument);
  Matrix withNaN = Matrix::Identity(2, 2);
  withNaN(1, 1) = std::nan("");
  EXPECT_THROW(NoiseModel::fromCovariance(withNaN), std::invalid_argument);
  EXPECT_THROW(NoiseModel::fromSqrtInformation(notSymmetric.transpose()), std::invalid_argument);
  EXPECT_THROW(NoiseModel::fromSigmas(Vector2(1.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(NoiseModel::fromCovariance(Matrix(2, 3)), std::invalid_argument);
}

TEST(RobustKernel, WeightIsTheDerivativeOfTheCost) {
  const HuberKernel huber(1.5);
  const CauchyKernel cauchy(0.7);
  for (double s : {0.01, 0.5, 2.0, 2.3, 9.0, 100.0}) {
    const double h = 1e-6 * s;
    EXPECT_NEAR(huber.weight(s), (huber.cost(s + h) - huber.cost(s - h)) / (2 * h), 1e-6) << s;
    EXPECT_NEAR(cauchy.weight(s), (cauchy.cost(s + h) - cauchy.cost(s - h)) / (2 * h), 1e-6) << s;
  }
  // Quadratic near zero, continuous at the Huber threshold.
  EXPECT_DOUBLE_EQ(huber.cost(1.0), 1.0);
  EXPECT_NEAR(huber.cost(2.25 - 1e-12), huber.cost(2.25 + 1e-12), 1e-9);
  EXPECT_NEAR(cauchy.cost(1e-8), 1e-8, 1e-15);
}

TEST(RobustKernel, NoiseModelCarriesTheKernel) {
  const SharedNoiseModel model =
      NoiseModel::isotropic(2, 1.0)->withRobustKernel(std::make_shared<HuberKernel>(1.0));
  ASSERT_NE(model->robustKernel(), nullptr);
  EXPECT_EQ(model->robustKernel()->name(), "huber");
  EXPECT_EQ(NoiseModel::isotropic(2, 1.0)->robustKernel(), nullptr);
}

TEST(NoiseModel, LargestWhitenedNormInABoxAndLargestErrorEntryAreAttained) {
  // A correlated 2D model: the box's largest ‖R c‖ is at the corner whose signs go against the correlation, and an
  // error along Σ's i-th column attains |e_i| = ‖r‖ √Σ_ii.
  Matrix covariance(2, 2);
  covariance << 0.04, 0.018, 0.018, 0.01;
  const SharedNoiseModel noise = NoiseModel::fromCovariance(covariance);
  const Vector2 halfWidths(0.1, 0.05);
  double largest = 0.0;
  for (double s0 : {-1.0, 1.0}) {
    for (double s1 : {-1.0, 1.0}) largest = std::max(largest, noise->whiten(Vector2(s0 * 0.1, s1 * 0.05)).norm());
  }
  EXPECT_NEAR(noise->largestWhitenedNormInBox(halfWidths), largest, 1e-12);
  EXPECT_NEAR(noise->largestWhitenedNormInBox(halfWidths), noise->whiten(Vector2(0.1, -0.05)).norm(), 1e-12);
  EXPECT_GT(noise->largestWhitenedNormInBox(halfWidths), noise->whiten(Vector2(0.1, 0.05)).norm() * 4.0);
  for (int i : {0, 1}) {
    const Vector e = covariance.col(i);  // maximises e_i for a given eᵀΣ⁻¹e
    const double chi2 = noise->whiten(e).squaredNorm();
    EXPECT_NEAR(noise->largestErrorEntry(i, chi2), std::abs(e(i)), 1e-12);
    EXPECT_NEAR(noise->largestErrorEntry(i, 4.0), 2.0 * std::sqrt(covariance(i, i)), 1e-12);
  }
}

TEST(NoiseModel, LargestWhitenedNormInABoxIsItsLargestCornerInThreeDimensions) {
  Matrix covariance(3, 3);
  covariance << 0.04, -0.01, 0.005, -0.01, 0.09, 0.02, 0.005, 0.02, 0.01;
  const SharedNoiseModel noise = NoiseModel::fromCovariance(covariance);
  const Vector3 halfWidths(0.2, 0.1, 0.05);
  double largest = 0.0;
  for (int signs = 0; signs < 8; ++signs) {
    const Vector3 corner((signs & 1 ? -1 : 1) * 0.2, (signs & 2 ? -1 : 1) * 0.1, (signs & 4 ? -1 : 1) * 0.05);
    largest = std::max(largest, noise->whiten(corner).norm());
  }
  EXPECT_NEAR(noise->largestWhitenedNormInBox(halfWidths), largest, 1e-12);
  for (int trial = 0; trial < 200; ++trial) {  // no point of the box goes further
    const Vector3 inside = Vector3::Random().cwiseProduct(halfWidths);
    EXPECT_LE(noise->whiten(inside).norm(), largest + 1e-12);
  }
  EXPECT_THROW(noise->largestWhitenedNormInBox(Vector2(0.1, 0.1)), std::invalid_argument);
}
