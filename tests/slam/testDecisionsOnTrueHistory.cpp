// Decisions on the true history (SemanticSlamOptions::decideOnTrueHistory, docs/association-front-end.md §8b): the
// graph is `known`'s, the front end's own decisions are recorded and scored, never applied; a mislabelled sighting
// of one of two look-alikes is decided onto the other, and every other decision of the scene is right.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "semslam/eval/RunEvaluation.h"
#include "semslam/slam/LoopClosureBranches.h"
#include "semslam/slam/SemanticSlam.h"

namespace semslam {
namespace {

/// Two look-alikes A (4, 0.1) and B (4, −0.1), classes 0 and 1, 0.2 m apart, and C (2, 3), class 2; 3 classes, a
/// categorical classifier wrong 10 % of the time; a relative-position sensor (range 10 m, opening π, σ 0.1 m
/// declared, detections exact). Step 0 (pose known) sees all three with their own labels; four steps of exact but
/// uncertain odometry follow (σ 0.3 m declared per step); step 5 sees A labelled 1 (misclassified) and C; step 6
/// sees A labelled 0 and a clutter point far from every landmark.
struct LookAlikes {
  LogHeader header;
  Point2 a{4.0, 0.1}, b{4.0, -0.1}, c{2.0, 3.0}, clutter{7.0, -4.0};

  LookAlikes() {
    header.classes = 3;
    header.semantic = SemanticKind::Label;
    header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
    header.classifier.misclassification = 0.1;
    header.sensor.kind = SensorKind::RelativePosition;
    header.sensor.maxRange = 10.0;
    header.sensor.fieldOfView = std::numbers::pi;
    header.initialPose = PosePrior{SE2(), Vector3(1e-6, 1e-6, 1e-8).asDiagonal().toDenseMatrix()};
  }

  static SE2 poseAt(int k) { return SE2(0.1 * k, 0.0, 0.0); }

  static Detection detectionOf(const Point2& world, int k, int label, int truth) {
    Detection d;
    d.geometry = poseAt(k).transformTo(world);
    d.covariance = 0.01 * Matrix::Identity(2, 2);
    d.label = label;
    d.truthId = truth;
    return d;
  }

  MeasurementLog log() const {
    MeasurementLog log;
    log.header = header;
    for (int k = 0; k <= 6; ++k) {
      TimeStep step;
      step.time = k;
      step.truePose = poseAt(k);
      if (k > 0) step.odometry = Odometry{SE2(0.1, 0.0, 0.0), Vector3(0.09, 0.09, 1e-6).asDiagonal().toDenseMatrix()};
      if (k == 0) step.detections = {detectionOf(a, k, 0, 0), detectionOf(b, k, 1, 1), detectionOf(c, k, 2, 2)};
      if (k == 5) step.detections = {detectionOf(a, k, 1, 0), detectionOf(c, k, 2, 2)};
      if (k == 6) step.detections = {detectionOf(a, k, 0, 0), detectionOf(clutter, k, 2, kNotALandmark)};
      log.steps.push_back(step);
    }
    return log;
  }
};

SemanticSlamOptions onTrueHistory(AssociationStrategy strategy) {
  SemanticSlamOptions options;
  options.strategy = strategy;
  options.decideOnTrueHistory = true;
  return options;
}

RunResult run(const MeasurementLog& log, const SemanticSlamOptions& options) {
  SemanticSlam slam(log.header, options);
  for (const TimeStep& step : log.steps) slam.addStep(step);
  slam.finish();
  return slam.result(false);
}

TEST(DecisionsOnTrueHistory, AMislabelledLookAlikeIsDecidedOntoItsTwinAndNothingElseIsWrong) {
  const MeasurementLog log = LookAlikes().log();
  for (AssociationStrategy strategy : {AssociationStrategy::MaximumLikelihood, AssociationStrategy::MaxMixture,
                                       AssociationStrategy::MaxMixtureNullHypothesis, AssociationStrategy::Gpda}) {
    const RunResult result = run(log, onTrueHistory(strategy));
    ASSERT_EQ(result.historyDecisions.size(), log.steps.size());
    // Step 0: three first sightings, nothing mapped: every one unassigned, rightly. Landmarks are A 0, B 1, C 2.
    for (const HistoryDecision& d : result.historyDecisions[0]) {
      EXPECT_FALSE(d.decided.has_value()) << strategyName(strategy);
      EXPECT_FALSE(d.right.has_value());
    }
    // Step 5: A labelled as B's class: under the pose's uncertainty the 0.2 m between them does not outweigh the
    // label's odds (0.9 against 0.05), so A's detection is decided onto B. C is C.
    EXPECT_EQ(result.historyDecisions[5][0].decided, 1) << strategyName(strategy);
    EXPECT_EQ(result.historyDecisions[5][0].right, 0);
    EXPECT_EQ(result.historyDecisions[5][1].decided, 2) << strategyName(strategy);
    // Step 6: A with its own label is A; the clutter point is left unassigned.
    EXPECT_EQ(result.historyDecisions[6][0].decided, 0) << strategyName(strategy);
    EXPECT_FALSE(result.historyDecisions[6][1].decided.has_value()) << strategyName(strategy);
    EXPECT_FALSE(result.historyDecisions[6][1].right.has_value());

    const RunMetrics metrics = evaluateRun(log, result).metrics;
    EXPECT_DOUBLE_EQ(metrics.decisionAccuracyReal, 5.0 / 6.0) << strategyName(strategy);
    EXPECT_EQ(metrics.decisionsResightingElsewhere, 1);
    EXPECT_EQ(metrics.decisionsResightingUnassigned, 0);
    EXPECT_EQ(metrics.decisionsFirstSightingForced, 0);
    EXPECT_DOUBLE_EQ(metrics.decisionClutterRejected, 1.0);
    EXPECT_EQ(result.method, strategyName(strategy) + "@true-history");
  }
}

TEST(DecisionsOnTrueHistory, TheGraphIsKnownsAndTheDecisionsAreNotApplied) {
  const MeasurementLog log = LookAlikes().log();
  SemanticSlamOptions known;
  known.strategy = AssociationStrategy::Known;
  const RunResult truth = run(log, known);
  const RunResult decided = run(log, onTrueHistory(AssociationStrategy::MaxMixtureNullHypothesis));
  EXPECT_EQ(decided.associations, truth.associations);  // A's step-5 detection on A, not on B; clutter on none
  ASSERT_EQ(decided.poses.size(), truth.poses.size());
  for (std::size_t k = 0; k < truth.poses.size(); ++k) {
    const SE2& x = std::get<SE2>(decided.poses[k]);
    const SE2& y = std::get<SE2>(truth.poses[k]);
    EXPECT_LT((x.translation() - y.translation()).norm(), 1e-8) << "pose " << k;
    EXPECT_LT(std::abs(x.theta() - y.theta()), 1e-8) << "pose " << k;
  }
  ASSERT_EQ(decided.landmarks.size(), truth.landmarks.size());
  for (std::size_t j = 0; j < truth.landmarks.size(); ++j) {
    EXPECT_LT((std::get<Point2>(decided.landmarks[j].state) - std::get<Point2>(truth.landmarks[j].state)).norm(), 1e-8);
  }
  EXPECT_TRUE(truth.historyDecisions.empty());  // `known` decides nothing
}

TEST(DecisionsOnTrueHistory, IsRefusedWhereNothingIsDecidedOrNothingCouldBeScored) {
  const LookAlikes scene;
  SemanticSlamOptions known = onTrueHistory(AssociationStrategy::Known);
  EXPECT_THROW(SemanticSlam(scene.header, known), std::invalid_argument);
  SemanticSlamOptions threshold = onTrueHistory(AssociationStrategy::MaxMixtureNullHypothesis);
  threshold.birth = BirthRule::Threshold;  // no joint assignment: no decision of the unassigned rule to score
  EXPECT_THROW(SemanticSlam(scene.header, threshold), std::invalid_argument);
  SemanticSlamOptions branches = onTrueHistory(AssociationStrategy::MaxMixtureNullHypothesis);
  EXPECT_EQ(LoopClosureBranches::window(branches), 0);  // nothing decided is applied: nothing to branch on
  branches.loopClosureBranchWindow = 16;
  EXPECT_THROW(LoopClosureBranches::window(branches), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
