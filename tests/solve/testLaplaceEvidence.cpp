// Laplace's approximation of a factor graph's evidence (solve/LaplaceEvidence.h), against closed forms: the
// evidence of two Gaussian measurements of one point, N(z₁ − z₂; 0, R₁ + R₂) (exact: the factors are linear), of
// measurements on separate points (1: each integrates to 1), and of a chain of SE(2) poses with a prior and
// odometry at its mode (1 again: the integral of a normalised density over the group, which the Laplace form
// reproduces through the Jacobians' determinants).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/MaxMixtureFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/solve/LaplaceEvidence.h"
#include "semslam/solve/SparseCholesky.h"

namespace semslam {
namespace {

Matrix covariance(double sxx, double sxy, double syy) {
  Matrix c(2, 2);
  c << sxx, sxy, sxy, syy;
  return c;
}

const Point2 kFirst(5.0, 1.0), kSecond(5.3, 0.7);
const Matrix kFirstCovariance = covariance(0.04, 0.01, 0.09), kSecondCovariance = covariance(0.16, -0.02, 0.05);

/// The two measurements' mode, x̂ = (R₁⁻¹ + R₂⁻¹)⁻¹ (R₁⁻¹ z₁ + R₂⁻¹ z₂).
Point2 fusedMode() {
  const Matrix a = kFirstCovariance.inverse(), b = kSecondCovariance.inverse();
  return (a + b).inverse() * (a * kFirst + b * kSecond);
}

TEST(LaplaceEvidence, TwoMeasurementsOfOnePointGiveTheGaussianOfTheirDifference) {
  FactorGraph graph;
  graph.emplace<PriorFactor<Point2>>(landmarkKey(0), kFirst, NoiseModel::fromCovariance(kFirstCovariance));
  graph.emplace<PriorFactor<Point2>>(landmarkKey(0), kSecond, NoiseModel::fromCovariance(kSecondCovariance));
  Values mode;
  mode.insert(landmarkKey(0), fusedMode());

  const Matrix sum = kFirstCovariance + kSecondCovariance;
  const Vector difference = kFirst - kSecond;
  const double expected = difference.dot(sum.inverse() * difference) + std::log((2.0 * std::numbers::pi * sum).determinant());
  EXPECT_NEAR(laplaceEvidenceScore(graph, mode), expected, 1e-10);
}

TEST(LaplaceEvidence, MeasurementsOfSeparatePointsIntegrateToOne) {
  FactorGraph graph;
  graph.emplace<PriorFactor<Point2>>(landmarkKey(0), kFirst, NoiseModel::fromCovariance(kFirstCovariance));
  graph.emplace<PriorFactor<Point2>>(landmarkKey(1), kSecond, NoiseModel::fromCovariance(kSecondCovariance));
  Values mode;
  mode.insert(landmarkKey(0), kFirst);
  mode.insert(landmarkKey(1), kSecond);
  EXPECT_NEAR(laplaceEvidenceScore(graph, mode), 0.0, 1e-10);
}

TEST(LaplaceEvidence, APoseChainWithAPriorAndOdometryIntegratesToOne) {
  FactorGraph graph;
  Values mode;
  SE2 pose(1.0, -2.0, 0.3);
  graph.emplace<PriorFactor<SE2>>(poseKey(0), pose, NoiseModel::fromSigmas(Vector3(0.1, 0.2, 0.05)));
  mode.insert(poseKey(0), pose);
  for (int k = 1; k < 6; ++k) {
    const SE2 increment(1.0, 0.1 * k, 0.2 - 0.05 * k);
    graph.emplace<BetweenFactor<SE2>>(poseKey(k - 1), poseKey(k), increment,
                                      NoiseModel::fromSigmas(Vector3(0.05 * k, 0.03, 0.01 * k)));
    pose = pose * increment;
    mode.insert(poseKey(k), pose);
  }
  EXPECT_NEAR(laplaceEvidenceScore(graph, mode), 0.0, 1e-9);
}

TEST(LaplaceEvidence, ALooseVariableOrAFactorWithoutNormaliserIsRefused) {
  Values mode;
  mode.insert(poseKey(0), SE2());
  mode.insert(poseKey(1), SE2(1.0, 0.0, 0.0));
  FactorGraph floating;  // odometry with no prior: the chain's place is not determined
  floating.emplace<BetweenFactor<SE2>>(poseKey(0), poseKey(1), SE2(1.0, 0.0, 0.0), NoiseModel::isotropic(3, 0.1));
  EXPECT_THROW(laplaceEvidenceScore(floating, mode), std::domain_error);

  FactorGraph mixture;
  const auto component = std::make_shared<PriorFactor<SE2>>(poseKey(0), SE2(), NoiseModel::isotropic(3, 0.1));
  mixture.add(std::make_shared<MaxMixtureFactor>(std::vector<MaxMixtureFactor::Component>{{component, 1.0}}));
  EXPECT_THROW(laplaceEvidenceScore(mixture, mode), std::invalid_argument);
}

TEST(SparseCholesky, LogDeterminantMatchesTheDenseOne) {
  Matrix dense(4, 4);
  dense << 4.0, 1.0, 0.0, 0.5, 1.0, 3.0, 0.2, 0.0, 0.0, 0.2, 2.0, 0.3, 0.5, 0.0, 0.3, 5.0;
  const SparseCholesky::SparseMatrix upper = dense.triangularView<Eigen::Upper>().toDenseMatrix().sparseView();
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factorize(upper));
  EXPECT_NEAR(cholesky.logDeterminant(), std::log(dense.determinant()), 1e-12);
}

}  // namespace
}  // namespace semslam
