// Prior, between and relative-point factors: error conventions and Jacobians against finite differences.

#include <gtest/gtest.h>

#include <random>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "support/FactorTesting.h"

using namespace semslam;
using semslam::test::expectJacobiansMatch;

namespace {

std::mt19937 rng(20261122);

double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

SE2 randomSE2() { return SE2(uniform(-5, 5), uniform(-5, 5), uniform(-3.1, 3.1)); }

SE3 randomSE3() {
  const Vector3 axis = Vector3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
  return SE3(SO3::fromAxisAngle(axis, uniform(-3.1, 3.1)), Point3(uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)));
}

Matrix randomCovariance(int d) {
  Matrix a(d, d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) a(i, j) = uniform(-1, 1);
  return 0.1 * (a * a.transpose()) + 0.05 * Matrix::Identity(d, d);
}

}  // namespace

TEST(PriorFactor, ErrorIsLogOfPriorInverseTimesValue) {
  const SE2 prior(1.0, 2.0, 0.5), x(1.5, 1.0, -0.3);
  const PriorFactor<SE2> factor(0, prior, NoiseModel::isotropic(3, 1.0));
  Values values;
  values.insert(0, x);
  EXPECT_TRUE(factor.unwhitenedError(values).isApprox(SE2::Log(prior.inverse() * x), 1e-12));
  EXPECT_NEAR(factor.chi2(values), SE2::Log(prior.inverse() * x).squaredNorm(), 1e-12);
}

TEST(PriorFactor, JacobiansMatchFiniteDifferences) {
  for (int trial = 0; trial < 20; ++trial) {
    Values values;
    values.insert(0, randomSE2());
    values.insert(1, randomSE3());
    values.insert(2, Point2(uniform(-3, 3), uniform(-3, 3)));
    expectJacobiansMatch(PriorFactor<SE2>(0, randomSE2(), NoiseModel::fromCovariance(randomCovariance(3))), values);
    expectJacobiansMatch(PriorFactor<SE3>(1, randomSE3(), NoiseModel::fromCovariance(randomCovariance(6))), values);
    expectJacobiansMatch(PriorFactor<Point2>(2, Point2(1, 2), NoiseModel::fromCovariance(randomCovariance(2))),
                         values);
  }
}

TEST(BetweenFactor, ErrorIsLogOfMeasurementInverseTimesRelativePose) {
  const SE3 xi = randomSE3(), xj = randomSE3(), z = randomSE3();
  const BetweenFactor<SE3> factor(0, 1, z, NoiseModel::isotropic(6, 1.0));
  Values values;
  values.insert(0, xi);
  values.insert(1, xj);
  EXPECT_TRUE(factor.unwhitenedError(values).isApprox(SE3::Log(z.inverse() * (xi.inverse() * xj)), 1e-10));
}

TEST(BetweenFactor, JacobiansMatchFiniteDifferences) {
  for (int trial = 0; trial < 30; ++trial) {
    Values values;
    const SE2 a = randomSE2(), b = randomSE2();
    const SE3 c = randomSE3(), d = randomSE3();
    values.insert(0, a);
    values.insert(1, b);
    values.insert(2, c);
    values.insert(3, d);
    values.insert(4, Point3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)));
    values.insert(5, Point3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)));
    // Measurements both near the truth (small error) and far from it (large error, Jr⁻¹ far from I).
    const SE2 z2 = trial % 2 ? a.between(b) * SE2::Exp(Vector3(0.01, -0.02, 0.03)) : randomSE2();
    const SE3 z3 = trial % 2 ? c.between(d) * SE3::Exp(Vector6::Constant(0.02)) : randomSE3();
    expectJacobiansMatch(BetweenFactor<SE2>(0, 1, z2, NoiseModel::fromCovariance(randomCovariance(3))), values);
    expectJacobiansMatch(BetweenFactor<SE3>(2, 3, z3, NoiseModel::fromCovariance(randomCovariance(6))), values);
    expectJacobiansMatch(
        BetweenFactor<Point3>(4, 5, Point3(0.1, 0.2, 0.3), NoiseModel::fromCovariance(randomCovariance(3))), values);
  }
}

TEST(RelativePointFactor, ErrorAndJacobians) {
  for (int trial = 0; trial < 20; ++trial) {
    Values values;
    const SE2 pose2 = randomSE2();
    const SE3 pose3 = randomSE3();
    const Point2 landmark2(uniform(-5, 5), uniform(-5, 5));
    const Point3 landmark3(uniform(-5, 5), uniform(-5, 5), uniform(-5, 5));
    values.insert(poseKey(0), pose2);
    values.insert(landmarkKey(0), landmark2);
    values.insert(poseKey(1), pose3);
    values.insert(landmarkKey(1), landmark3);
    const RelativePointFactor<SE2, Point2> planar(poseKey(0), landmarkKey(0), Point2(0.5, -0.5),
                                                  NoiseModel::fromCovariance(randomCovariance(2)));
    const RelativePointFactor<SE3, Point3> spatial(poseKey(1), landmarkKey(1), Point3(0.5, -0.5, 1.0),
                                                   NoiseModel::fromCovariance(randomCovariance(3)));
    const Point2 expected = pose2.rotation().matrix().transpose() * (landmark2 - pose2.translation()) -
                            Point2(0.5, -0.5);
    EXPECT_TRUE(planar.unwhitenedError(values).isApprox(expected, 1e-12));
    expectJacobiansMatch(planar, values);
    expectJacobiansMatch(spatial, values);
  }
}

TEST(NoiseModelFactor, RobustKernelScalesErrorAndKeepsTheExactGradient) {
  const SharedNoiseModel noise =
      NoiseModel::isotropic(3, 0.1)->withRobustKernel(std::make_shared<CauchyKernel>(1.0));
  const PriorFactor<SE2> factor(0, SE2(), noise);
  Values values;
  values.insert(0, SE2(0.5, -0.3, 0.2));
  const double s = (SE2::Log(SE2(0.5, -0.3, 0.2)) / 0.1).squaredNorm();
  EXPECT_NEAR(factor.chi2(values), CauchyKernel(1.0).cost(s), 1e-12);
  // Gradient of ½ρ: Jᵀr from the IRLS-scaled linearization must equal the numerical gradient of ½ chi2.
  LinearizedFactor lin;
  factor.linearize(values, lin);
  EXPECT_NEAR(lin.chi2, factor.chi2(values), 1e-12);
  const Vector gradient = lin.jacobians[0].transpose() * lin.whitenedError;
  for (int i = 0; i < 3; ++i) {
    Vector3 delta = Vector3::Zero();
    delta(i) = 1e-6;
    Values plus = values, minus = values;
    plus.update(0, values.at<SE2>(0).retract(delta));
    minus.update(0, values.at<SE2>(0).retract(-delta));
    EXPECT_NEAR(gradient(i), 0.5 * (factor.chi2(plus) - factor.chi2(minus)) / 2e-6, 1e-5 * (1 + gradient.norm()));
  }
}

TEST(NoiseModelFactor, RejectsNoiseOfTheWrongDimension) {
  EXPECT_THROW(PriorFactor<SE2>(0, SE2(), NoiseModel::isotropic(2, 1.0)), std::invalid_argument);
  EXPECT_THROW(PriorFactor<SE2>(0, SE2(), nullptr), std::invalid_argument);
}
