// The label split test of one landmark's detections (LandmarkSplit.h, docs/association-front-end.md §5d), against
// its closed form for position detections of isotropic noise.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "semslam/association/LandmarkSplit.h"

using namespace semslam;

namespace {

constexpr double kSigma = 0.2;       // detection σ per axis [m]
constexpr double kLogDensity = -4.0; // ln ρ: about one unassigned landmark per 55 m²

/// P(label | class) of a 3-class classifier that is right with probability 0.9: the column of `label`.
Vector labelLikelihoods(int label) {
  Vector column = Vector::Constant(3, 0.05);
  column(label) = 0.9;
  return column;
}

/// A position detection z of a landmark whose estimate is `estimate`, with the pose held fixed: whitened residual
/// (l − z) / σ and whitened Jacobian I / σ.
SplitEvidence detectionAt(const Vector& z, const Vector& estimate, int label) {
  return {labelLikelihoods(label), (estimate - z) / kSigma, Matrix::Identity(2, 2) / kSigma};
}

/// ln((1/M) Σ_c Π_i s_i(c)) by brute force.
double logLabels(const std::vector<int>& labels) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    double product = 1.0;
    for (int label : labels) product *= labelLikelihoods(label)(c);
    sum += product;
  }
  return std::log(sum / 3.0);
}

/// The closed form of the score for two groups of positions with isotropic σ: the geometry at δ_A = δ_B under
/// Σ_d = σ² (1/n_A + 1/n_B) I, the labels, the prior of a second object, and P_D = 0.5: ln 2 per detection.
double closedFormScore(const std::vector<int>& firstLabels, const std::vector<int>& secondLabels) {
  const double variance = kSigma * kSigma * (1.0 / firstLabels.size() + 1.0 / secondLabels.size());
  const double logGaussian = -std::log(2.0 * std::numbers::pi * variance);
  std::vector<int> all = firstLabels;
  all.insert(all.end(), secondLabels.begin(), secondLabels.end());
  return logGaussian + logLabels(all) - logLabels(firstLabels) - logLabels(secondLabels) - kLogDensity +
         static_cast<double>(all.size()) * std::log(2.0);
}

Vector point(double x, double y) {
  Vector p(2);
  p << x, y;
  return p;
}

}  // namespace

TEST(LandmarkSplit, TwoLabelledGroupsSplitWithTheClosedFormScoreAndTheSecondGroupsOwnPosition) {
  // The second group's detections come first in time: the landmark keeps the group of its first detection.
  const Vector estimate = point(4.0, 1.0);
  const std::vector<Vector> first = {point(3.9, 1.1), point(4.05, 0.9), point(4.1, 1.05), point(3.95, 0.95),
                                     point(4.0, 1.0), point(3.98, 1.02), point(4.02, 0.97), point(4.01, 1.01)};
  const std::vector<Vector> second = {point(4.2, 1.15), point(4.3, 1.2), point(4.15, 1.3), point(4.25, 1.25),
                                      point(4.2, 1.2), point(4.22, 1.18), point(4.18, 1.22), point(4.21, 1.19)};
  std::vector<SplitEvidence> evidence;
  for (const Vector& z : first) evidence.push_back(detectionAt(z, estimate, 2));
  for (const Vector& z : second) evidence.push_back(detectionAt(z, estimate, 0));
  const std::optional<LandmarkSplitDecision> split = bestLandmarkSplit(evidence, kLogDensity);
  ASSERT_TRUE(split);
  EXPECT_EQ(split->firstClass, 2);
  EXPECT_EQ(split->secondClass, 0);
  std::vector<bool> expected(16, false);
  for (std::size_t i = 8; i < 16; ++i) expected[i] = true;
  EXPECT_EQ(split->second, expected);
  EXPECT_NEAR(split->score, closedFormScore(std::vector<int>(8, 2), std::vector<int>(8, 0)), 1e-9);
  EXPECT_LT(split->score, 0.0);
  Vector secondMean = Vector::Zero(2);
  for (const Vector& z : second) secondMean += z / 8.0;
  EXPECT_LT((estimate + split->secondDelta - secondMean).norm(), 1e-12);  // δ_B: from the estimate to B's mean
}

TEST(LandmarkSplit, OneObjectWithAnOccasionalWrongLabelDoesNotSplit) {
  // Ten detections of class 1 around one point, one of them labelled 0 (what 10 % misclassification gives).
  const Vector estimate = point(0.0, 5.0);
  std::vector<SplitEvidence> evidence;
  for (int i = 0; i < 10; ++i) {
    const double angle = 0.6 * i;
    evidence.push_back(detectionAt(point(0.1 * std::cos(angle), 5.0 + 0.1 * std::sin(angle)), estimate,
                                   i == 4 ? 0 : 1));
  }
  EXPECT_FALSE(bestLandmarkSplit(evidence, kLogDensity));
}

TEST(LandmarkSplit, TheSecondObjectNeedsEnoughLabelsToOutweighItsPriorAndItsMisses) {
  // One place: the geometry favours one object, by ln N(0; 0, Σ_d) − ln ρ, and so does every detection (ln 2: the
  // other object, in view, missed); each label of the second class adds ln(0.9 / 0.05) to the other side.
  const Vector estimate = point(2.0, 2.0);
  std::vector<SplitEvidence> evidence;
  for (int i = 0; i < 10; ++i) evidence.push_back(detectionAt(estimate, estimate, 1));
  for (int i = 0; i < 3; ++i) evidence.push_back(detectionAt(estimate, estimate, 0));
  EXPECT_FALSE(bestLandmarkSplit(evidence, kLogDensity));  // three labels in thirteen: misclassifications
  EXPECT_GT(closedFormScore(std::vector<int>(10, 1), std::vector<int>(3, 0)), 0.0);
  for (int extra = 0; extra < 4; ++extra) evidence.push_back(detectionAt(estimate, estimate, 0));
  const std::optional<LandmarkSplitDecision> split = bestLandmarkSplit(evidence, kLogDensity);
  ASSERT_TRUE(split);  // seven: a second object
  EXPECT_NEAR(split->score, closedFormScore(std::vector<int>(10, 1), std::vector<int>(7, 0)), 1e-9);
  // A sparser field (ρ lower) makes a second object at that spot less likely a priori, and a split harder; so
  // does a higher detection probability (more misses to explain).
  EXPECT_FALSE(bestLandmarkSplit(evidence, kLogDensity + split->score - 1e-6));
  EXPECT_FALSE(bestLandmarkSplit(evidence, kLogDensity, 0.6));
  EXPECT_TRUE(bestLandmarkSplit(evidence, kLogDensity, 0.4));
}

TEST(LandmarkSplit, AnExactClassifierSplitsOnOneContradictingLabel) {
  const Vector estimate = point(1.0, 0.0);
  std::vector<SplitEvidence> evidence;
  for (int i = 0; i < 3; ++i) evidence.push_back(detectionAt(estimate, estimate, 0));
  evidence.push_back(detectionAt(estimate, estimate, 1));
  for (SplitEvidence& detection : evidence) {
    detection.classLikelihoods = (detection.classLikelihoods.array() > 0.5).cast<double>().matrix();
  }
  const std::optional<LandmarkSplitDecision> split = bestLandmarkSplit(evidence, kLogDensity);
  ASSERT_TRUE(split);
  EXPECT_EQ(split->second, (std::vector<bool>{false, false, false, true}));
  EXPECT_TRUE(std::isinf(split->score));
}

TEST(LandmarkSplit, NothingToSplitWithoutTwoDetectionsOrTwoClasses) {
  const Vector estimate = point(1.0, 0.0);
  EXPECT_FALSE(bestLandmarkSplit({}, kLogDensity));
  EXPECT_FALSE(bestLandmarkSplit({detectionAt(estimate, estimate, 0)}, kLogDensity));
  SplitEvidence unlabelled = detectionAt(estimate, estimate, 0);
  unlabelled.classLikelihoods = Vector::Ones(1);
  EXPECT_FALSE(bestLandmarkSplit({unlabelled, unlabelled, unlabelled}, kLogDensity));
}

TEST(LandmarkSplit, DetectionsOfInconsistentSizesOrADetectionProbabilityOutsideItsRangeThrow) {
  const Vector estimate = point(1.0, 0.0);
  SplitEvidence wide = detectionAt(estimate, estimate, 1);
  wide.positionJacobian = Matrix::Identity(2, 3);
  EXPECT_THROW(bestLandmarkSplit({detectionAt(estimate, estimate, 0), wide}, kLogDensity), std::invalid_argument);
  SplitEvidence fourClasses = detectionAt(estimate, estimate, 1);
  fourClasses.classLikelihoods = Vector::Constant(4, 0.25);
  EXPECT_THROW(bestLandmarkSplit({detectionAt(estimate, estimate, 0), fourClasses}, kLogDensity),
               std::invalid_argument);
  const std::vector<SplitEvidence> two = {detectionAt(estimate, estimate, 0), detectionAt(estimate, estimate, 1)};
  EXPECT_THROW(bestLandmarkSplit(two, kLogDensity, 1.0), std::invalid_argument);
  EXPECT_THROW(bestLandmarkSplit(two, kLogDensity, -0.1), std::invalid_argument);
  EXPECT_THROW(bestLandmarkSplit(two, kLogDensity, std::nan("")), std::invalid_argument);
}
