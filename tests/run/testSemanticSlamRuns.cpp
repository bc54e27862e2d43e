// Paper B's pipeline (slam/SemanticSlam.h): every strategy on small simulated runs with known truth, the front
// end's weights against a closed form, the null hypothesis against clutter, and determinism.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"
#include "semslam/run/RunMethod.h"
#include "semslam/sim/Aliased2dScenario.h"
#include "semslam/sim/Aliased2dSimulator.h"
#include "support/GaussianDensity.h"

using namespace semslam;
using semslam::test::logGaussian;

namespace {

MeasurementLog simulatedRun(double clutter, std::uint64_t seed, int dimension = 2, double misclassification = 0.1) {
  PathOptions path;
  path.dimension = dimension;
  path.steps = 80;
  path.loops = 2;
  std::mt19937 rng(static_cast<unsigned>(seed));
  SemanticSimOptions options;
  options.classes = 3;
  options.landmarks = 12;
  options.clutter = clutter;
  options.misclassification = misclassification;
  options.fieldOfView = 0.0;
  return simulateSemantic(generatePath(path, rng), options, seed);
}

MethodRun run(const MeasurementLog& log, AssociationStrategy strategy, double gate = AssociationGate::kDefaultConfidence) {
  MethodOptions options;
  options.method = methodFor(strategy);
  options.slam.gateConfidence = gate;
  options.runFolder = false;
  return runMethod(log, options);
}

}  // namespace

TEST(SemanticSlam, EveryStrategyAssociatesASimulatedRunAndLocalisesLikeKnownAssociation) {
  const MeasurementLog log = simulatedRun(0.0, 3);
  const MethodRun known = run(log, AssociationStrategy::Known);
  EXPECT_EQ(known.evaluation.metrics.daAccuracy, 1.0);
  EXPECT_LT(known.evaluation.metrics.ateRmse, 1.0);
  for (AssociationStrategy strategy : allStrategies()) {
    const MethodRun result = run(log, strategy);
    const RunMetrics& m = result.evaluation.metrics;
    EXPECT_GE(m.daAccuracy, 0.97) << strategyName(strategy);
    EXPECT_LE(m.ateRmse, 1.5 * known.evaluation.metrics.ateRmse + 0.05) << strategyName(strategy);
    EXPECT_LE(*m.landmarksEstimated, 14) << strategyName(strategy);  // 12 true, few duplicates
    EXPECT_EQ(result.result.poses.size(), log.steps.size());
  }
}

TEST(SemanticSlam, NullHypothesisTakesClutterThatMaxMixturesMustAssociate) {
  // Without the warm start, whose first solve lets a gated clutter detection pull its (young) landmark before the
  // mixture chooses (docs/max-mixtures.md: the warm start trades this for robustness to poor odometry).
  const MeasurementLog log = simulatedRun(1.0, 5);
  MethodOptions options;
  options.runFolder = false;
  options.slam.warmStart = false;
  options.slam.birth = BirthRule::Threshold;  // paper B's pipeline: no provisional landmarks to drop the clutter
  options.method = Method::MaxMixtureNullHypothesis;
  const MethodRun withNull = runMethod(log, options);
  options.method = Method::MaxMixture;
  const MethodRun without = runMethod(log, options);
  ASSERT_GT(*withNull.evaluation.metrics.daClutter, 20);
  EXPECT_GT(*withNull.evaluation.metrics.daNull, 0);  // some clutter went to the null hypothesis
  EXPECT_EQ(without.evaluation.metrics.daNull.value_or(0), 0);
  EXPECT_GT(withNull.evaluation.metrics.daAccuracy, without.evaluation.metrics.daAccuracy)
      << "null " << withNull.evaluation.metrics.daAccuracy << " vs " << without.evaluation.metrics.daAccuracy;
}

TEST(SemanticSlam, FrontEndWeightsAreTheClosedFormMarginalLikelihoodTimesTheClassPredictive) {
  // A known-but-uncertain map: pose prior N(x̄, diag(0.5², 0.5², 1e-8)) (the heading nearly known, so the
  // relative-position model is linear to ~1e-7), landmark priors N(l̄_j, 0.3² I); a zero-motion odometry step with
  // covariance diag(0.1², 0.1², 1e-8), then one relative-position detection with a label. With Σ_t = 0.25 + 0.01
  // (isotropic, so the body-frame tangent needs no rotation):
  //   weight_j ∝ N(z; R̄ᵀ(l̄_j − t̄), Σ_t + Σ_j + Σ_z) · Σ_c P(label | c) P(c | l_j),  P(c | l_j) uniform.
  MeasurementLog log;
  log.header.dimension = 2;
  log.header.classes = 2;
  log.header.semantic = SemanticKind::Label;
  log.header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  log.header.classifier.misclassification = 0.2;
  log.header.sensor.kind = SensorKind::RelativePosition;
  const SE2 robot(0.5, -0.3, 0.4);
  log.header.initialPose = PosePrior{robot, Vector3(0.25, 0.25, 1e-8).asDiagonal().toDenseMatrix()};
  const std::vector<Point2> map = {{3.0, 1.0}, {3.4, 1.8}, {2.0, 3.0}};
  for (int j = 0; j < 3; ++j) log.header.landmarkPriors.push_back({j, map[j], 0.09 * Matrix::Identity(2, 2)});
  Detection detection;
  detection.geometry = Vector2(2.6, 0.5);
  detection.covariance = 0.04 * Matrix::Identity(2, 2);
  detection.label = 1;

  SemanticSlamOptions options;
  options.strategy = AssociationStrategy::MaximumLikelihood;
  options.birth = BirthRule::Threshold;  // paper B's weights (the unassigned rule's are in testUnassignedHypothesis)
  options.gateConfidence = 1.0 - 1e-12;  // every landmark a candidate
  SemanticSlam slam(log.header, options);
  TimeStep first{0.0, std::nullopt, {}, robot};
  TimeStep second{1.0, Odometry{SE2(), Vector3(0.01, 0.01, 1e-8).asDiagonal().toDenseMatrix()}, {detection}, robot};
  slam.addStep(first);
  slam.addStep(second);
  const DetectionRecord& record = slam.detections().at(0);
  ASSERT_EQ(record.candidates.size(), 3u);

  const Matrix2 R = robot.rotation().matrix();
  std::vector<double> expected;
  double sum = 0.0;
  for (int j = 0; j < 3; ++j) {
    const Vector2 predicted = R.transpose() * (map[j] - robot.translation());
    const Matrix2 S = (0.25 + 0.01 + 0.09 + 0.04) * Matrix2::Identity();
    const double semantic = 0.5 * 0.2 + 0.5 * 0.8;  // uniform class belief: Σ_c P(1 | c) / 2
    expected.push_back(std::exp(logGaussian(detection.geometry, predicted, S)) * semantic);
    sum += expected.back();
  }
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(record.weights[j], expected[j] / sum, 1e-6) << "landmark " << j;
}

TEST(SemanticSlam, SameLogSameResultBitForBit) {
  const MeasurementLog log = simulatedRun(0.5, 9);
  for (AssociationStrategy strategy : {AssociationStrategy::Gpda, AssociationStrategy::MaxMixtureNullHypothesis}) {
    const MethodRun a = run(log, strategy), b = run(log, strategy);
    ASSERT_EQ(a.result.poses.size(), b.result.poses.size());
    for (std::size_t k = 0; k < a.result.poses.size(); ++k) {
      EXPECT_EQ(std::get<SE2>(a.result.poses[k]).translation(), std::get<SE2>(b.result.poses[k]).translation());
    }
    EXPECT_EQ(a.result.associations, b.result.associations);
  }
}

TEST(SemanticSlam, ThreeDimensionalRunsWork) {
  const MeasurementLog log = simulatedRun(0.0, 4, 3);
  for (AssociationStrategy strategy : {AssociationStrategy::Known, AssociationStrategy::MaxMixtureNullHypothesis}) {
    const MethodRun result = run(log, strategy);
    EXPECT_GE(result.evaluation.metrics.daAccuracy, 0.95) << strategyName(strategy);
    EXPECT_LT(result.evaluation.metrics.ateRmse, 1.0) << strategyName(strategy);
  }
}

TEST(SemanticSlam, AnExactClassifierModelRulesCandidatesOutInsteadOfFailing) {
  // p = 0: a label different from a landmark's certain class has likelihood 0 under it; such a landmark is no
  // candidate (clutter carries random labels, so this happens).
  const MeasurementLog log = simulatedRun(0.5, 6, 2, 0.0);
  for (AssociationStrategy strategy : allStrategies()) {
    const MethodRun result = run(log, strategy);
    EXPECT_GE(result.evaluation.metrics.daAccuracy, 0.8) << strategyName(strategy);
  }
}

TEST(SemanticSlam, RejectsLogsThatBreakTheStepOrder) {
  const MeasurementLog log = simulatedRun(0.0, 3);
  SemanticSlam slam(log.header, {});
  EXPECT_THROW(slam.addStep(log.steps.at(1)), std::invalid_argument);  // odometry on the first step
  slam.addStep(log.steps.at(0));
  EXPECT_THROW(slam.addStep(log.steps.at(0)), std::invalid_argument);  // no odometry after it
}

TEST(SemanticSlam, EveryMethodRunsOnAliased2dTracksWhosePosedLandmarksHaveNoObservedOrientation) {
  // Paper A's scenario: objects with a pose, seen by a relative-position sensor, so a new landmark's orientation is
  // observed by nothing; without its orientation prior the system was singular (ml, gpda, mm stopped).
  for (int track = 0; track < 3; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(defaultAliased2dScenario(), 4, track, 20, 3);
    for (BirthRule birth : {BirthRule::Threshold, BirthRule::Unassigned}) {
      for (AssociationStrategy strategy : {AssociationStrategy::Known, AssociationStrategy::MaximumLikelihood,
                                           AssociationStrategy::Gpda, AssociationStrategy::MaxMixture,
                                           AssociationStrategy::MaxMixtureNullHypothesis}) {
        MethodOptions options;
        options.method = methodFor(strategy);
        options.slam.birth = birth;
        options.runFolder = false;
        MethodRun result;
        ASSERT_NO_THROW(result = runMethod(log, options)) << strategyName(strategy) << " track " << track;
        EXPECT_TRUE(std::isfinite(result.evaluation.metrics.ateRmse)) << strategyName(strategy);
        EXPECT_FALSE(result.result.landmarks.empty());
        for (const Matrix& covariance : result.result.poseCovariances) EXPECT_TRUE(covariance.allFinite());
      }
    }
  }
}
