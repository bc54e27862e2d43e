// BranchScore (slam/BranchScore.h), −2 ln of a run's evidence, against §5's merge test in closed form: two
// detections, from a pose that is known, of one object (one landmark) or of two (two landmarks) differ in score by
//   Δ = −2 ln( N(z₁ − z₂; 0, R₁ + R₂) · M Σ_c P(c | s₁) P(c | s₂) / ρ ),
// the Gaussian of the two positions' difference, the agreement of their labels (each under the uniform class
// prior) and the birth density ρ = μ / V of a second landmark (docs/association-front-end.md §5, §10).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "semslam/slam/BranchScore.h"

namespace semslam {
namespace {

constexpr double kMisclassification = 0.1;
constexpr int kClasses = 3;
const Point2 kFirst(5.0, 1.0), kSecond(5.4, 0.7);

Matrix covariance(double sxx, double sxy, double syy) {
  Matrix c(2, 2);
  c << sxx, sxy, sxy, syy;
  return c;
}
const Matrix kFirstCovariance = covariance(0.04, 0.01, 0.09), kSecondCovariance = covariance(0.16, -0.02, 0.05);

LogHeader header() {
  LogHeader h;
  h.classes = kClasses;
  h.semantic = SemanticKind::Label;
  h.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  h.classifier.misclassification = kMisclassification;
  h.sensor.kind = SensorKind::RelativePosition;
  h.sensor.maxRange = 30.0;
  h.sensor.fieldOfView = 2.0 * std::numbers::pi;
  h.initialPose = PosePrior{SE2(), 1e-16 * Matrix::Identity(3, 3)};  // the pose known
  return h;
}

Detection detection(const Point2& position, const Matrix& covariance, int label, int truthId) {
  Detection d;
  d.geometry = position;
  d.covariance = covariance;
  d.label = label;
  d.truthId = truthId;
  return d;
}

/// A `known` run whose first step sees `first` and whose second step sees `second`, both from the same pose, scored
/// at its own μ (1) or at `unassignedRate`.
double scoreOfTwoSteps(const LogHeader& h, const Detection& first, const Detection& second,
                       std::optional<double> unassignedRate = std::nullopt) {
  SemanticSlamOptions options;
  options.strategy = AssociationStrategy::Known;
  SemanticSlam run(h, options);
  TimeStep one, two;
  one.detections.push_back(first);
  two.time = 1.0;
  two.odometry = Odometry{SE2(), 1e-16 * Matrix::Identity(3, 3)};
  two.detections.push_back(second);
  run.addStep(one);
  run.addStep(two);
  return unassignedRate ? branchScore(run, *unassignedRate) : branchScore(run);
}

/// Two detections, labelled 0 and 1, of objects `firstId` and `secondId`.
double scoreOf(int firstId, int secondId) {
  return scoreOfTwoSteps(header(), detection(kFirst, kFirstCovariance, 0, firstId),
                         detection(kSecond, kSecondCovariance, 1, secondId));
}

TEST(BranchScore, OneObjectAgainstTwoIsTheMergeTest) {
  const Matrix sum = kFirstCovariance + kSecondCovariance;
  const Vector difference = kFirst - kSecond;
  const double geometric =
      difference.dot(sum.inverse() * difference) + std::log((2.0 * std::numbers::pi * sum).determinant());
  // Labels 0 and 1: P(c | s) = (0.9, 0.05, 0.05) and (0.05, 0.9, 0.05).
  const double agreement = kClasses * (0.9 * 0.05 + 0.05 * 0.9 + 0.05 * 0.05);
  const double logBirthDensity = -std::log(std::numbers::pi * 30.0 * 30.0);  // μ = 1 over the 30 m disc
  const double expected = geometric - 2.0 * std::log(agreement) + 2.0 * logBirthDensity;
  EXPECT_NEAR(scoreOf(0, 0) - scoreOf(0, 1), expected, 1e-6);
}

// A detection that no factor holds (here `known`'s clutter) is explained by the unassigned density λ(z); a landmark
// seen once explains its detection as well as that: its Gaussian integrates to the Jacobian of the back-projection,
// and its prior is ρ, so together ρ·|J| = λ(z). The two scores are equal, for a relative-position sensor (λ = ρ) and
// for range-bearing (λ = ρ r): without the λ term the clutter would score 2 ln(1/λ) lower (15.9 and 8.6 here).
TEST(BranchScore, ADetectionOnNoFactorScoresAsALandmarkSeenOnce) {
  const Detection first = detection(kFirst, kFirstCovariance, 0, 0);
  EXPECT_NEAR(scoreOfTwoSteps(header(), first, detection(kSecond, kSecondCovariance, 1, 1)),
              scoreOfTwoSteps(header(), first, detection(kSecond, kSecondCovariance, 1, kNotALandmark)), 1e-6);

  LogHeader rangeBearing = header();
  rangeBearing.sensor.kind = SensorKind::RangeBearing;
  rangeBearing.sensor.fieldOfView = 1.2;  // ρ = 1 / (0.6 · 30²)
  const Matrix noise = covariance(0.04, 0.0, 0.0004);
  const Detection near = detection(Point2(4.0, 0.1), noise, 0, 0);
  const Detection far = detection(Point2(7.5, -0.2), noise, 1, 1);  // range 7.5 m, bearing −0.2 rad
  Detection clutter = far;
  clutter.truthId = kNotALandmark;
  EXPECT_NEAR(scoreOfTwoSteps(rangeBearing, near, far), scoreOfTwoSteps(rangeBearing, near, clutter), 1e-6);
}

// The branches of a split are scored at one μ (LoopClosureBranches; μ estimated from the run differs between
// them): at μ instead of the run's own μ = 1, every active landmark's prior ln ρ and every unexplained detection's
// ln λ move by ln μ, so the score moves by −2 (L + U) ln μ, L active landmarks and U detections on no factor.
TEST(BranchScore, AtAnotherRateTheScoreMovesByTheLandmarksAndTheUnexplainedDetections) {
  const Detection first = detection(kFirst, kFirstCovariance, 0, 0);
  const Detection second = detection(kSecond, kSecondCovariance, 1, 0);
  Detection apart = second, clutter = second;
  apart.truthId = 1;
  clutter.truthId = kNotALandmark;
  for (double rate : {0.05, 0.3, 4.0}) {
    const double shift = -2.0 * std::log(rate);
    EXPECT_NEAR(scoreOfTwoSteps(header(), first, second, rate) - scoreOfTwoSteps(header(), first, second),
                1.0 * shift, 1e-6) << "one landmark, μ = " << rate;
    EXPECT_NEAR(scoreOfTwoSteps(header(), first, apart, rate) - scoreOfTwoSteps(header(), first, apart),
                2.0 * shift, 1e-6) << "two landmarks, μ = " << rate;
    EXPECT_NEAR(scoreOfTwoSteps(header(), first, clutter, rate) - scoreOfTwoSteps(header(), first, clutter),
                2.0 * shift, 1e-6) << "a landmark and a detection on no factor, μ = " << rate;
  }
  EXPECT_THROW(scoreOfTwoSteps(header(), first, second, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
