// Decisions on the true history (DecisionAccuracy.h): the header's worked example, each kind of wrong decision
// alone, the fractions without detections of their kind, refusals, and evaluateRun's plumbing (unknown truth left
// out, sizes checked).

#include <gtest/gtest.h>

#include <cmath>

#include "semslam/core/InputError.h"
#include "semslam/eval/DecisionAccuracy.h"
#include "semslam/eval/RunEvaluation.h"

namespace semslam {
namespace {

constexpr int a = 0, b = 1, c = 2;
const std::optional<int> none = std::nullopt;

ScoredDecision decision(int truth, std::optional<int> decided, std::optional<int> right) {
  return {truth, {decided, right}};
}

TEST(DecisionAccuracy, HeaderExample) {
  // Re-sightings of a on a (right), of a on b (elsewhere), of b unassigned; a first sighting of c unassigned
  // (right); one clutter detection on a.
  const DecisionAccuracy d = evaluateDecisions({decision(a, a, a), decision(a, b, a), decision(b, none, b),
                                                decision(c, none, none), decision(kNotALandmark, a, none)});
  EXPECT_EQ(d.realTotal, 4u);
  EXPECT_EQ(d.realCorrect, 2u);
  EXPECT_DOUBLE_EQ(d.accuracyReal, 0.5);
  EXPECT_EQ(d.resightingsElsewhere, 1u);
  EXPECT_EQ(d.resightingsUnassigned, 1u);
  EXPECT_EQ(d.firstSightingsForced, 0u);
  EXPECT_EQ(d.clutterTotal, 1u);
  EXPECT_EQ(d.clutterRejected, 0u);
  EXPECT_DOUBLE_EQ(d.clutterRejectedFraction, 0.0);
}

TEST(DecisionAccuracy, AFirstSightingPutOnAMappedLandmarkIsForced) {
  const DecisionAccuracy d = evaluateDecisions({decision(c, a, none), decision(c, none, none)});
  EXPECT_EQ(d.firstSightingsForced, 1u);
  EXPECT_EQ(d.resightingsElsewhere, 0u);
  EXPECT_DOUBLE_EQ(d.accuracyReal, 0.5);
}

TEST(DecisionAccuracy, ClutterIsRejectedOnlyWhenUnassigned) {
  const DecisionAccuracy d = evaluateDecisions(
      {decision(kNotALandmark, none, none), decision(kNotALandmark, none, none), decision(kNotALandmark, b, none)});
  EXPECT_DOUBLE_EQ(d.clutterRejectedFraction, 2.0 / 3.0);
  EXPECT_TRUE(std::isnan(d.accuracyReal));  // no true-landmark detection
  EXPECT_TRUE(std::isnan(evaluateDecisions({decision(a, a, a)}).clutterRejectedFraction));
}

TEST(DecisionAccuracy, RefusesWhatNoRunCanReport) {
  EXPECT_THROW(evaluateDecisions({decision(kNotALandmark, none, a)}), std::invalid_argument);  // clutter has none
  EXPECT_THROW(evaluateDecisions({decision(kUnknownTruth, none, none)}), std::invalid_argument);
}

/// A log of two steps: step 0 sees a (first sighting), step 1 sees a again, one detection of unknown truth and one
/// of clutter.
MeasurementLog twoStepLog() {
  MeasurementLog log;
  log.header.sensor.kind = SensorKind::RelativePosition;
  Detection d;
  d.geometry = Vector2(1.0, 0.0);
  d.covariance = Matrix::Identity(2, 2);
  TimeStep first;
  first.truePose = SE2();
  d.truthId = a;
  first.detections = {d};
  TimeStep second = first;
  second.time = 1.0;
  second.odometry = Odometry{SE2(), Matrix::Identity(3, 3)};
  Detection unknown = d, clutter = d;
  unknown.truthId = kUnknownTruth;
  clutter.truthId = kNotALandmark;
  second.detections = {d, unknown, clutter};
  log.steps = {first, second};
  return log;
}

RunResult twoStepResult() {
  RunResult result;
  result.poses = {SE2(), SE2()};
  result.associations = {{0}, {0, none, none}};
  // The unknown-truth detection's decision is wrong by any reading: it must be left out, not counted.
  result.historyDecisions = {{{none, none}}, {{0, 0}, {0, none}, {none, none}}};
  return result;
}

TEST(DecisionAccuracy, EvaluateRunScoresTheDecisionsAndLeavesUnknownTruthOut) {
  const RunMetrics metrics = evaluateRun(twoStepLog(), twoStepResult()).metrics;
  EXPECT_DOUBLE_EQ(metrics.decisionAccuracyReal, 1.0);
  EXPECT_DOUBLE_EQ(metrics.decisionClutterRejected, 1.0);
  EXPECT_EQ(metrics.decisionsResightingElsewhere, 0);
  EXPECT_EQ(metrics.decisionsFirstSightingForced, 0);
}

TEST(DecisionAccuracy, EvaluateRunWithoutDecisionsLeavesTheMetricsOut) {
  RunResult result = twoStepResult();
  result.historyDecisions.clear();
  const RunMetrics metrics = evaluateRun(twoStepLog(), result).metrics;
  EXPECT_TRUE(std::isnan(metrics.decisionAccuracyReal));
  EXPECT_FALSE(metrics.decisionsResightingElsewhere.has_value());
}

TEST(DecisionAccuracy, EvaluateRunRefusesDecisionsThatDoNotMatchTheLog) {
  RunResult result = twoStepResult();
  result.historyDecisions[1].pop_back();
  EXPECT_THROW(evaluateRun(twoStepLog(), result), InputError);
  result.historyDecisions.pop_back();
  EXPECT_THROW(evaluateRun(twoStepLog(), result), InputError);
}

}  // namespace
}  // namespace semslam
