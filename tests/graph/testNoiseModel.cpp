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
