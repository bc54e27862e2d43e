// NEES under the right-perturbation convention: errors drawn from the stated covariance give a mean NEES of d;
// the chi-square band of the mean.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <random>

#include "semslam/core/ChiSquare.h"
#include "semslam/eval/Nees.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

template <int D>
MatrixN<D, 1> sample(const MatrixN<D, D>& lower, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  MatrixN<D, 1> z;
  for (int i = 0; i < D; ++i) z(i) = normal(rng);
  return lower * z;
}

Matrix3 planarCovariance() {
  // Strongly anisotropic and correlated, so that the side of the perturbation matters.
  Matrix3 a;
  a << 0.5, 0.0, 0.0,  //
      0.05, 0.05, 0.0,  //
      0.02, 0.01, 0.1;
  return a * a.transpose();
}

TEST(Nees, PoseErrorIsTheRightPerturbation) {
  const SE2 estimate(3.0, -2.0, 2.0);
  const Vector3 e(0.3, -0.1, 0.2);
  EXPECT_LT((poseError(estimate, estimate * SE2::Exp(e)) - e).norm(), 1e-14);
  Vector6 e6;
  e6 << 0.1, 0.2, -0.3, 0.05, -0.02, 0.3;
  Vector6 g;
  g << 1.0, 2.0, 3.0, 0.4, 0.5, -0.6;
  const SE3 estimate3 = SE3::Exp(g);
  EXPECT_LT((poseError(estimate3, estimate3 * SE3::Exp(e6)) - e6).norm(), 1e-13);
  // NEES of a known error: eᵀ Σ⁻¹ e with a diagonal Σ.
  const Matrix3 sigma = Vector3(0.04, 0.01, 0.25).asDiagonal();
  EXPECT_NEAR(poseNees(estimate, estimate * SE2::Exp(e), sigma), 0.09 / 0.04 + 0.01 / 0.01 + 0.04 / 0.25, 1e-12);
}

TEST(Nees, SamplesFromTheStatedCovarianceHaveMeanNeesThree) {
  std::mt19937 rng(12345);
  const Matrix3 sigma = planarCovariance();
  const Matrix3 lower = sigma.llt().matrixL();
  const SE2 estimate(3.0, -2.0, 2.0);
  const int n = 20000;
  std::vector<double> right, left;
  for (int i = 0; i < n; ++i) {
    const Vector3 e = sample<3>(lower, rng);
    right.push_back(poseNees(estimate, estimate * SE2::Exp(e), sigma));
    left.push_back(poseNees(estimate, SE2::Exp(e) * estimate, sigma));  // the wrong convention
  }
  const NeesSummary summary = summarizeNees(right, 3);
  // The mean of n χ²_3 values has standard deviation sqrt(6 / n) = 0.017: 4 standard deviations allowed.
  EXPECT_NEAR(summary.mean, 3.0, 0.07);
  EXPECT_EQ(summary.count, static_cast<std::size_t>(n));
  EXPECT_EQ(summary.dimension, 3);
  // The band is a 95 % test: over 200 batches of 100 poses about 95 % of the batch means fall inside it
  // (binomial standard deviation 1.5 %).
  int inside = 0;
  for (int batch = 0; batch < 200; ++batch) {
    const std::vector<double> values(right.begin() + 100 * batch, right.begin() + 100 * (batch + 1));
    if (summarizeNees(values, 3).withinBand()) ++inside;
  }
  EXPECT_GE(inside, 182);
  EXPECT_LE(inside, 198);
  // A left-perturbation truth does not fit this covariance: its NEES is far from 3.
  EXPECT_FALSE(summarizeNees(left, 3).withinBand());
  EXPECT_GT(std::abs(summarizeNees(left, 3).mean - 3.0), 1.0);
}

TEST(Nees, SpatialSamplesHaveMeanNeesSix) {
  std::mt19937 rng(777);
  Matrix6 a = Matrix6::Zero();
  a.diagonal() << 0.2, 0.1, 0.3, 0.05, 0.02, 0.1;
  a(3, 0) = 0.03;
  a(5, 1) = -0.02;
  const Matrix6 sigma = a * a.transpose();
  const Matrix6 lower = sigma.llt().matrixL();
  Vector6 g;
  g << 5.0, -1.0, 2.0, 0.3, 1.0, -2.0;
  const SE3 estimate = SE3::Exp(g);
  std::vector<double> values;
  for (int i = 0; i < 20000; ++i) values.push_back(poseNees(estimate, estimate * SE3::Exp(sample<6>(lower, rng)), sigma));
  const NeesSummary summary = summarizeNees(values, 6);
  EXPECT_NEAR(summary.mean, 6.0, 0.1);  // standard deviation sqrt(12 / n) = 0.024
}

TEST(Nees, PointNees) {
  const Matrix2 sigma = Vector2(4.0, 0.25).asDiagonal();
  EXPECT_NEAR(pointNees(Vector2(1.0, 1.0), Vector2(3.0, 0.5), sigma), 1.0 + 1.0, 1e-15);
}

TEST(Nees, BandOfTheMean) {
  const NeesSummary one = summarizeNees({2.0}, 3);
  EXPECT_NEAR(one.lower, 0.21579528262389788, 1e-12);
  EXPECT_NEAR(one.upper, 9.3484036044961458, 1e-12);
  const std::vector<double> hundred(100, 2.0);
  const NeesSummary many = summarizeNees(hundred, 2, 0.99);
  EXPECT_DOUBLE_EQ(many.mean, 2.0);
  EXPECT_NEAR(many.lower, chiSquareQuantile(0.005, 200) / 100.0, 1e-14);
  EXPECT_NEAR(many.upper, chiSquareQuantile(0.995, 200) / 100.0, 1e-14);
  EXPECT_TRUE(many.withinBand());
  const NeesSummary empty = summarizeNees({}, 3);
  EXPECT_TRUE(std::isnan(empty.mean));
  EXPECT_FALSE(empty.withinBand());
}

TEST(Nees, InvalidCovarianceThrows) {
  const SE2 pose;
  Matrix3 notPositive = Matrix3::Identity();
  notPositive(2, 2) = -1.0;
  EXPECT_THROW(poseNees(pose, pose, notPositive), InputError);
  Matrix3 asymmetric = Matrix3::Identity();
  asymmetric(0, 1) = 0.5;
  EXPECT_THROW(poseNees(pose, pose, asymmetric), InputError);
  EXPECT_THROW(poseNees(pose, pose, Matrix::Identity(2, 2)), InputError);
  EXPECT_THROW(summarizeNees({1.0, -1.0}, 3), InputError);
  EXPECT_THROW(summarizeNees({1.0}, 0), InputError);
}

}  // namespace
}  // namespace semslam
