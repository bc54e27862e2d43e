// The unassigned hypothesis and the joint assignment of paper B's front end (docs/association-front-end.md):
// its density against the closed form, the switch point d*(S, λ) through the whole front end, exclusion (two
// detections of one step never share a landmark), and the joint assignment score (§4, "Joint compatibility").

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

#include "semslam/association/UnassignedHypothesis.h"
#include "semslam/slam/SemanticSlam.h"
#include "support/GaussianDensity.h"

namespace semslam {
namespace {

using test::logGaussian;

/// A robot at a known pose, one mapped landmark at (3, 1) with covariance 0.09 I, a relative-position sensor of
/// range 10 m and opening π; every covariance isotropic, so the innovation covariance is S = 0.39 I (as in
/// testSemanticSlamRuns' closed-form case: 0.25 pose + 0.01 odometry + 0.09 landmark + 0.04 detection).
struct OneLandmark {
  MeasurementLog log;
  SE2 robot{0.5, -0.3, 0.4};
  Point2 landmark{3.0, 1.0};
  double s = 0.39;

  OneLandmark() {
    log.header.sensor.kind = SensorKind::RelativePosition;
    log.header.sensor.maxRange = 10.0;
    log.header.sensor.fieldOfView = std::numbers::pi;
    log.header.initialPose = PosePrior{robot, Vector3(0.25, 0.25, 1e-8).asDiagonal().toDenseMatrix()};
    log.header.landmarkPriors.push_back({0, landmark, 0.09 * Matrix::Identity(2, 2)});
  }

  Vector2 predicted() const { return robot.rotation().matrix().transpose() * (landmark - robot.translation()); }

  Detection detectionAt(const Vector2& geometry) const {
    Detection d;
    d.geometry = geometry;
    d.covariance = 0.04 * Matrix::Identity(2, 2);
    return d;
  }

  /// Runs two steps, the second with `detections`, and returns the front end.
  SemanticSlam run(const std::vector<Detection>& detections, AssociationStrategy strategy) const {
    SemanticSlamOptions options;
    options.strategy = strategy;
    options.birth = BirthRule::Unassigned;
    SemanticSlam slam(log.header, options);
    slam.addStep(TimeStep{0.0, std::nullopt, {}, robot});
    slam.addStep(TimeStep{1.0, Odometry{SE2(), Vector3(0.01, 0.01, 1e-8).asDiagonal().toDenseMatrix()}, detections,
                          robot});
    return slam;
  }
};

TEST(UnassignedHypothesis, DensityIsTheRateOverTheFieldAreaForARelativePositionSensor) {
  OneLandmark setup;
  const UnassignedHypothesis unassigned(setup.log.header, 2.0);
  // V = Φ r_max² / 2 = π · 100 / 2; λ = μ / V, the same everywhere for a Cartesian measurement.
  const double expected = std::log(2.0 / (std::numbers::pi * 100.0 / 2.0));
  EXPECT_NEAR(unassigned.logDensity(setup.detectionAt(Vector2(1.0, 2.0))), expected, 1e-12);
  EXPECT_NEAR(unassigned.logDensity(setup.detectionAt(Vector2(7.0, -1.0))), expected, 1e-12);
}

// μ from the run (docs/association-front-end.md §10, "μ from the run"): the Gamma(w μ₀, w) prior's posterior mean
// after T counted steps with n unassigned detections, (w μ₀ + n) / (w + T); the density moves with it.
TEST(UnassignedHypothesis, AnEstimatedRateIsThePosteriorMeanOfTheCountedSteps) {
  OneLandmark setup;
  UnassignedHypothesis estimated(setup.log.header, 2.0, 4.0);
  const double logVolume = std::log(std::numbers::pi * 100.0 / 2.0);
  const Detection anywhere = setup.detectionAt(Vector2(1.0, 2.0));
  EXPECT_DOUBLE_EQ(estimated.rate(), 2.0);  // the prior mean before any step
  for (int count : {3, 0, 1}) estimated.countStep(count);
  EXPECT_NEAR(estimated.rate(), (4.0 * 2.0 + 4.0) / (4.0 + 3.0), 1e-15);
  EXPECT_NEAR(estimated.logDensity(anywhere), std::log(12.0 / 7.0) - logVolume, 1e-12);
  for (int step = 0; step < 10000; ++step) estimated.countStep(step % 4 == 0 ? 1 : 0);  // the data's rate, 0.25
  EXPECT_NEAR(estimated.rate(), 0.25, 2e-3);

  // withRate: the same field at a constant μ, which counting leaves alone.
  UnassignedHypothesis fixed = estimated.withRate(0.5);
  fixed.countStep(7);
  EXPECT_DOUBLE_EQ(fixed.rate(), 0.5);
  EXPECT_NEAR(fixed.logDensity(anywhere), std::log(0.5) - logVolume, 1e-12);
  UnassignedHypothesis constant(setup.log.header, 2.0);
  constant.countStep(5);
  EXPECT_DOUBLE_EQ(constant.rate(), 2.0);

  for (double weight : {0.0, -1.0, std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(UnassignedHypothesis(setup.log.header, 1.0, weight), std::invalid_argument) << weight;
  }
  EXPECT_THROW(estimated.countStep(-1), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(estimated.withRate(0.0)), std::invalid_argument);
}

// μ from the run with a memory of M steps: the counts discounted by γ = 1 − 1/M a step, the prior kept whole, so
// μ̂ = (w μ₀ + Σ γ^(T−i) n_i) / (w + Σ γ^(T−i)): it follows a rate that changes, where the plain estimate averages.
TEST(UnassignedHypothesis, AnEstimateWithAMemoryDiscountsOldStepsAndFollowsAChangedRate) {
  OneLandmark setup;
  UnassignedHypothesis remembering(setup.log.header, 2.0, 4.0, 10.0);
  const double gamma = 0.9;
  for (int count : {3, 0, 1}) remembering.countStep(count);
  const double n = (gamma * 3.0 + 0.0) * gamma + 1.0, t = (gamma + 1.0) * gamma + 1.0;
  EXPECT_NEAR(remembering.rate(), (4.0 * 2.0 + n) / (4.0 + t), 1e-15);
  // A memory of one step keeps only the last count: μ̂ = (w μ₀ + n_T) / (w + 1).
  UnassignedHypothesis lastStep(setup.log.header, 2.0, 4.0, 1.0);
  for (int count : {3, 0, 5}) lastStep.countStep(count);
  EXPECT_NEAR(lastStep.rate(), (8.0 + 5.0) / 5.0, 1e-15);
  // 2000 steps at rate 2, then 200 at rate 0.25: the remembering estimate is near the new rate, the plain one near
  // the run's average.
  UnassignedHypothesis plain(setup.log.header, 1.0, 10.0);
  UnassignedHypothesis recent(setup.log.header, 1.0, 10.0, 20.0);
  for (int step = 0; step < 2200; ++step) {
    const int count = step < 2000 ? 2 : (step % 4 == 0 ? 1 : 0);
    plain.countStep(count);
    recent.countStep(count);
  }
  EXPECT_GT(plain.rate(), 1.7);  // (10 + 4000 + 50) / (10 + 2200) ≈ 1.84
  // γ^200 ≈ 3.5e-5: the old steps are gone; Σ γ^i ≈ 20 recent steps holding ≈ 5 detections: (10 + 5) / (10 + 20).
  EXPECT_NEAR(recent.rate(), 0.5, 0.05);
  // Refused: a memory below one step or not finite, and a memory without an estimated rate.
  for (double memory : {0.0, 0.5, -3.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    EXPECT_THROW(UnassignedHypothesis(setup.log.header, 1.0, 4.0, memory), std::invalid_argument) << memory;
  }
  EXPECT_THROW(UnassignedHypothesis(setup.log.header, 1.0, std::nullopt, 10.0), std::invalid_argument);
}

// Through the front end: after T steps with nothing unassigned, μ̂ = w μ₀ / (w + T), and the switch point of the
// next detection is d*(S, λ) at that μ̂, not at μ₀: a detection between the two switch points goes to the
// landmark under the estimate and would start a new one under the constant μ₀ (whose switch point is nearer).
TEST(UnassignedHypothesis, TheFrontEndSwitchesAtTheDistanceOfTheEstimatedRate) {
  const OneLandmark setup;
  constexpr int kEmptySteps = 8;
  constexpr double kWeight = 2.0;
  const Odometry still{SE2(), Vector3(0.01, 0.01, 1e-8).asDiagonal().toDenseMatrix()};
  const double s = 0.25 + 0.01 * kEmptySteps + 0.09 + 0.04;  // pose + odometry + landmark + detection
  const auto run = [&](const Vector2& z, std::optional<double> weight) {
    SemanticSlamOptions options;
    options.strategy = AssociationStrategy::MaximumLikelihood;
    options.unassignedRateWeight = weight;
    SemanticSlam slam(setup.log.header, options);
    slam.addStep(TimeStep{0.0, std::nullopt, {}, setup.robot});
    for (int k = 1; k < kEmptySteps; ++k) slam.addStep(TimeStep{double(k), still, {}, setup.robot});
    EXPECT_NEAR(slam.unassignedHypothesis().rate(), weight ? kWeight / (kWeight + kEmptySteps) : 1.0, 1e-15);
    slam.addStep(TimeStep{double(kEmptySteps), still, {setup.detectionAt(z)}, setup.robot});
    return slam;
  };
  const UnassignedHypothesis field(setup.log.header);
  const double logVolumeTerm = field.logDensity(setup.detectionAt(setup.predicted()));  // ln(1 / V)
  const double estimatedRate = kWeight / (kWeight + kEmptySteps);
  const double dConstant = std::sqrt(switchDistanceSquared(logVolumeTerm, 2, 2.0 * std::log(s)));
  const double dEstimated =
      std::sqrt(switchDistanceSquared(logVolumeTerm + std::log(estimatedRate), 2, 2.0 * std::log(s)));
  ASSERT_GT(dEstimated, dConstant * 1.05);
  const Vector2 direction = Vector2(1.0, -1.0).normalized();
  const auto at = [&](double distance) { return Vector2(setup.predicted() + distance * std::sqrt(s) * direction); };
  for (double factor : {0.97, 1.03}) {
    const SemanticSlam estimated = run(at(factor * dEstimated), kWeight);
    EXPECT_EQ(estimated.detections().at(0).assigned.has_value(), factor < 1.0) << "at " << factor << " d*(μ̂)";
    // one step more counted, with the detection's decision
    EXPECT_NEAR(estimated.unassignedHypothesis().rate(),
                (kWeight + (factor < 1.0 ? 0.0 : 1.0)) / (kWeight + kEmptySteps + 1), 1e-15);
  }
  const SemanticSlam constant = run(at(0.5 * (dConstant + dEstimated)), std::nullopt);
  EXPECT_FALSE(constant.detections().at(0).assigned);
  const SemanticSlam estimated = run(at(0.5 * (dConstant + dEstimated)), kWeight);
  EXPECT_EQ(estimated.detections().at(0).assigned, std::optional<int>(0));
}

TEST(UnassignedHypothesis, RangeBearingDensityIsTheCartesianDensityTimesTheRange) {
  LogHeader header;
  header.sensor.kind = SensorKind::RangeBearing;
  UnassignedHypothesis unassigned(header);
  Detection far, near;
  far.geometry = Vector2(4.0, 0.3);
  near.geometry = Vector2(1.0, -0.5);
  unassigned.observe(far);
  unassigned.observe(near);
  EXPECT_DOUBLE_EQ(unassigned.maxRange(), 4.0);
  EXPECT_DOUBLE_EQ(unassigned.bearingSpan(), 1.0);  // 2 · max |bearing|, from the data
  const double cartesian = 1.0 / (1.0 * 16.0 / 2.0);
  EXPECT_NEAR(unassigned.logDensity(near), std::log(cartesian * 1.0), 1e-12);
  EXPECT_NEAR(unassigned.logDensity(far), std::log(cartesian * 4.0), 1e-12);
}

TEST(UnassignedHypothesis, TheSwitchDistanceIsWhereTheGaussianEqualsTheDensity) {
  const Matrix2 S = (Matrix2() << 0.5, 0.1, 0.1, 0.3).finished();
  const double logLambda = std::log(0.01);
  const double d2 = switchDistanceSquared(logLambda, 2, std::log(S.determinant()));
  ASSERT_GT(d2, 0.0);
  // A point at Mahalanobis distance d* along any direction has density λ.
  const Vector2 direction = Vector2(0.6, -0.8);
  const double scale = std::sqrt(d2 / direction.dot(S.inverse() * direction));
  EXPECT_NEAR(logGaussian(Vector2(scale * direction), Vector2::Zero(), S), logLambda, 1e-12);
  // A label the landmark explains twice as well as the prior moves the switch out by 2 ln 2.
  EXPECT_NEAR(switchDistanceSquared(logLambda, 2, std::log(S.determinant()), std::log(2.0)), d2 + 2.0 * std::log(2.0),
              1e-12);
}

TEST(UnassignedHypothesis, TheFrontEndSwitchesFromTheLandmarkToANewOneAtTheClosedFormDistance) {
  const OneLandmark setup;
  const UnassignedHypothesis unassigned(setup.log.header);
  const double logLambda = unassigned.logDensity(setup.detectionAt(setup.predicted()));
  const double dStar = std::sqrt(switchDistanceSquared(logLambda, 2, 2.0 * std::log(setup.s)));
  const Vector2 direction = Vector2(1.0, 1.0).normalized();
  for (double factor : {0.5, 0.97, 1.03, 1.5}) {
    const Vector2 z = setup.predicted() + factor * dStar * std::sqrt(setup.s) * direction;
    const SemanticSlam slam = setup.run({setup.detectionAt(z)}, AssociationStrategy::MaximumLikelihood);
    const DetectionRecord& record = slam.detections().at(0);
    if (factor < 1.0) {
      EXPECT_EQ(record.assigned, std::optional<int>(0)) << "at " << factor << " d*";
      EXPECT_EQ(slam.landmarks(), 1);
    } else {
      EXPECT_FALSE(record.assigned) << "at " << factor << " d*";
      EXPECT_TRUE(record.createdLandmark);
      EXPECT_EQ(slam.landmarks(), 2);
    }
  }
}

TEST(UnassignedHypothesis, TwoDetectionsOfOneStepNeverShareALandmark) {
  const OneLandmark setup;
  const Detection a = setup.detectionAt(setup.predicted() + Vector2(0.05, 0.0));
  const Detection b = setup.detectionAt(setup.predicted() - Vector2(0.0, 0.05));
  for (AssociationStrategy strategy : {AssociationStrategy::MaximumLikelihood, AssociationStrategy::Gpda,
                                       AssociationStrategy::MaxMixture, AssociationStrategy::MaxMixtureNullHypothesis}) {
    SemanticSlam slam = setup.run({a, b}, strategy);
    slam.finish();
    const RunResult result = slam.result(false);
    ASSERT_EQ(result.associations.at(1).size(), 2u);
    const std::optional<int> first = result.associations[1][0], second = result.associations[1][1];
    EXPECT_TRUE(!first || !second || *first != *second) << strategyName(strategy);
    EXPECT_EQ(slam.landmarks(), 2) << strategyName(strategy);  // the second detection started a landmark
  }
}

/// Two mapped landmarks 4 m apart, a pose known to 10 m, and a step that sees both 5 m off where the estimate puts
/// them (the same 5 m for both: the pose's error). Each pairing alone has a density below the unassigned density,
/// so the independent score starts two new landmarks; the joint score pays the pose's uncertainty once and pairs
/// both, each with its own landmark.
struct TwoLandmarksUnderABroadPose {
  MeasurementLog log;
  SE2 estimated{0.0, 0.0, 0.0};
  Vector2 poseError{3.0, -4.0};
  std::vector<Point2> landmarks{Point2(6.0, 0.0), Point2(6.0, 4.0)};

  TwoLandmarksUnderABroadPose() {
    log.header.sensor.kind = SensorKind::RelativePosition;
    log.header.sensor.maxRange = 10.0;
    log.header.sensor.fieldOfView = std::numbers::pi;
    log.header.initialPose = PosePrior{estimated, Vector3(100.0, 100.0, 1e-8).asDiagonal().toDenseMatrix()};
    for (int j = 0; j < 2; ++j) log.header.landmarkPriors.push_back({j, landmarks[j], 0.01 * Matrix::Identity(2, 2)});
  }

  SemanticSlam run(AssignmentScore score) const {
    SemanticSlamOptions options;
    options.strategy = AssociationStrategy::MaximumLikelihood;
    options.assignmentScore = score;
    SemanticSlam slam(log.header, options);
    const SE2 truth(poseError.x(), poseError.y(), 0.0);
    slam.addStep(TimeStep{0.0, std::nullopt, {}, truth});
    std::vector<Detection> detections;
    for (int j = 0; j < 2; ++j) {
      Detection d;
      d.geometry = truth.transformTo(landmarks[j]);
      d.covariance = 0.01 * Matrix::Identity(2, 2);
      d.truthId = j;
      detections.push_back(d);
    }
    slam.addStep(TimeStep{1.0, Odometry{SE2(), Vector3(1e-4, 1e-4, 1e-8).asDiagonal().toDenseMatrix()}, detections,
                          truth});
    return slam;
  }
};

TEST(UnassignedHypothesis, TheJointScorePairsReSightingsThatEachAloneWouldLeaveUnassigned) {
  const TwoLandmarksUnderABroadPose setup;
  const SemanticSlam independent = setup.run(AssignmentScore::Independent);
  for (int j = 0; j < 2; ++j) {
    const DetectionRecord& record = independent.detections().at(static_cast<std::size_t>(j));
    EXPECT_FALSE(record.assigned) << "detection " << j;
    EXPECT_TRUE(record.createdLandmark) << "detection " << j;
  }
  const SemanticSlam joint = setup.run(AssignmentScore::Joint);
  for (int j = 0; j < 2; ++j) {
    EXPECT_EQ(joint.detections().at(static_cast<std::size_t>(j)).assigned, std::optional<int>(j)) << "detection " << j;
  }
  EXPECT_EQ(joint.landmarks(), 2);
  // The pose moves onto the truth (within the detections' noise).
  const SE2 pose = joint.smoother().estimate<SE2>(poseKey(1));
  EXPECT_NEAR(pose.translation().x(), setup.poseError.x(), 0.2);
  EXPECT_NEAR(pose.translation().y(), setup.poseError.y(), 0.2);
}

TEST(UnassignedHypothesis, TheJointScoreNeedsAStrategyThatDecidesAndTheUnassignedRule) {
  const TwoLandmarksUnderABroadPose setup;
  SemanticSlamOptions options;
  options.assignmentScore = AssignmentScore::Joint;
  options.strategy = AssociationStrategy::Known;
  EXPECT_THROW(SemanticSlam(setup.log.header, options), std::invalid_argument);
  options.strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  options.birth = BirthRule::Threshold;
  EXPECT_THROW(SemanticSlam(setup.log.header, options), std::invalid_argument);
  EXPECT_EQ(parseAssignmentScore("joint"), AssignmentScore::Joint);
  EXPECT_EQ(assignmentScoreName(parseAssignmentScore("independent")), "independent");
  EXPECT_THROW(parseAssignmentScore("hungarian"), std::invalid_argument);
}

TEST(UnassignedHypothesis, TheJointScoreIsTheDefaultWhereAStepAssignmentIsScored) {
  SemanticSlamOptions options;
  for (AssociationStrategy strategy : {AssociationStrategy::MaximumLikelihood, AssociationStrategy::MaxMixture,
                                       AssociationStrategy::MaxMixtureNullHypothesis, AssociationStrategy::Gpda}) {
    options.strategy = strategy;
    EXPECT_EQ(resolvedAssignmentScore(options), AssignmentScore::Joint) << strategyName(strategy);
  }
  // Nothing to score: known assigns nothing, the threshold birth has no step assignment. The default is no refusal.
  const TwoLandmarksUnderABroadPose setup;
  options.strategy = AssociationStrategy::Known;
  EXPECT_EQ(resolvedAssignmentScore(options), AssignmentScore::Independent);
  EXPECT_NO_THROW(SemanticSlam(setup.log.header, options));
  options.strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  options.birth = BirthRule::Threshold;
  EXPECT_EQ(resolvedAssignmentScore(options), AssignmentScore::Independent);
  EXPECT_NO_THROW(SemanticSlam(setup.log.header, options));
  // Set, it is what it says.
  options.birth = BirthRule::Unassigned;
  options.assignmentScore = AssignmentScore::Independent;
  EXPECT_EQ(resolvedAssignmentScore(options), AssignmentScore::Independent);
}

}  // namespace
}  // namespace semslam
