// metrics.json: schema, key order, null for fields that do not apply, exact round trip, reader errors; and
// evaluateRun end to end on a small hand-made measurement log.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "support/InputErrorTesting.h"
#include "support/TempFile.h"
#include "semslam/io/RunMetricsFile.h"
#include "semslam/eval/RunEvaluation.h"
#include "semslam/eval/RunMetrics.h"
#include "semslam/core/InputError.h"
#include "semslam/core/Version.h"

namespace semslam {
namespace {

using test::TempFile;
using Json = nlohmann::ordered_json;

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

RunMetrics filledMetrics() {
  RunMetrics m;
  m.method = "mm+nh";
  m.dimension = 2;
  m.timeSeconds = 12.345678901234567;
  m.alignment = "se2";
  m.poses = 1200;
  m.ateRmse = 0.1;
  m.ateMean = 1.0 / 3.0;
  m.ateMedian = 1e-300;
  m.ateMax = 123456789.123456789;
  m.rotRmse = 0.2;
  m.rotMean = 0.15;
  m.rotMedian = 0.125;
  m.rotMax = 3.141592653589793;
  m.daAccuracy = 0.987654321;
  m.daCorrect = 80;
  m.daTotal = 81;
  m.daNull = 3;
  m.daClutter = 2;
  m.daAccuracyReal = 0.9;
  m.clutterRejected = 0.75;
  m.clutterRejectedMoving = 2.0 / 3.0;
  m.clutterRejectedFalsePositive = 1.0;
  m.landmarksEstimated = 18;
  m.landmarksTrue = 17;
  m.landmarkCountError = 1;
  m.landmarksMatched = 17;
  m.landmarkRmse = 0.25;
  m.classAccuracy = 16.0 / 17.0;
  m.neesMean = 3.2;
  m.neesCount = 1200;
  m.neesDof = 3;
  m.neesLower = 2.9;
  m.neesUpper = 3.1;
  m.entropy = 0.6730116670092565;
  m.detCov = 3.5e-7;
  m.errWmax = 0.5;
  m.errWavg = 1.0;
  m.ess = 2.7777777777777777;
  m.assocWeightMax = 0.6;
  m.disambiguatedFraction = 0.75;
  m.components = 3;
  m.histories = 2;
  return m;
}

TEST(RunMetrics, KeysInTheDocumentedOrder) {
  const Json json = Json::parse(runMetricsToJson(RunMetrics{}));
  std::vector<std::string> keys;
  for (const auto& item : json.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, runMetricsKeys());
  // The fields every method must write (issue list).
  for (const char* required : {"ate_rmse", "ate_mean", "ate_median", "ate_max", "rot_rmse", "rot_mean", "rot_median",
                               "rot_max", "da_accuracy", "landmarks_estimated", "landmarks_true", "class_accuracy",
                               "nees_mean", "time_s", "entropy", "det_cov", "err_wmax", "err_wavg", "ess"}) {
    EXPECT_TRUE(json.contains(required)) << required;
  }
  EXPECT_EQ(json["schema"], "semslam.metrics/1");
  EXPECT_EQ(json["version"], std::string(version()));  // the release that wrote the file
}

TEST(RunMetrics, FieldsThatDoNotApplyAreNull) {
  RunMetrics m;
  m.method = "ml";
  m.ateRmse = 0.5;
  m.neesMean = std::numeric_limits<double>::infinity();  // not finite: written as null too
  const Json json = Json::parse(runMetricsToJson(m));
  EXPECT_EQ(json["method"], "ml");
  EXPECT_EQ(json["ate_rmse"], 0.5);
  EXPECT_TRUE(json["nees_mean"].is_null());
  EXPECT_TRUE(json["entropy"].is_null());
  EXPECT_TRUE(json["da_accuracy"].is_null());
  EXPECT_TRUE(json["landmarks_true"].is_null());
  EXPECT_TRUE(json["alignment"].is_null());
  const RunMetrics back = runMetricsFromJson(json.dump());
  EXPECT_TRUE(std::isnan(back.entropy));
  EXPECT_TRUE(std::isnan(back.neesMean));
  EXPECT_FALSE(back.landmarksTrue);
  EXPECT_TRUE(back.alignment.empty());
}

TEST(RunMetrics, FileRoundTripIsExact) {
  const RunMetrics m = filledMetrics();
  TempFile file("", ".json");
  writeRunMetrics(file.path(), m);
  EXPECT_FALSE(std::filesystem::exists(file.path() + ".tmp"));
  const RunMetrics back = readRunMetrics(file.path());
  EXPECT_EQ(runMetricsToJson(back), runMetricsToJson(m));
  EXPECT_TRUE(sameBits(back.ateMean, m.ateMean));
  EXPECT_TRUE(sameBits(back.ateMedian, m.ateMedian));
  EXPECT_TRUE(sameBits(back.ateMax, m.ateMax));
  EXPECT_TRUE(sameBits(back.classAccuracy, m.classAccuracy));
  EXPECT_TRUE(sameBits(back.timeSeconds, m.timeSeconds));
  EXPECT_EQ(back.method, "mm+nh");
  EXPECT_EQ(back.alignment, "se2");
  EXPECT_EQ(back.landmarkCountError, 1);
  EXPECT_EQ(back.poses, 1200);
  // Writing twice gives the same bytes.
  EXPECT_EQ(runMetricsToJson(readRunMetrics(file.path())), runMetricsToJson(m));
}

TEST(RunMetrics, ReaderIsLenientAboutMissingAndUnknownKeysButNotTypes) {
  const RunMetrics partial =
      runMetricsFromJson(R"({"schema": "semslam.metrics/1", "ate_rmse": 2, "future_field": [1, 2]})");
  EXPECT_EQ(partial.ateRmse, 2.0);
  EXPECT_TRUE(std::isnan(partial.rotRmse));
  EXPECT_FALSE(partial.daTotal);

  test::expectInputError([] { runMetricsFromJson(R"({"ate_rmse": 1})", "m.json"); }, "m.json", 0, "schema");
  // A number beyond a double: nlohmann's out_of_range escaped as another exception (fuzz finding).
  test::expectInputError([] { runMetricsFromJson(R"({"schema": "semslam.metrics/1", "ate_rmse": 2e308})", "m.json"); },
                         "m.json", 0, "number overflow");
  test::expectInputError([] { runMetricsFromJson(R"({"schema": "semslam.metrics/2"})", "m.json"); }, "m.json", 0,
                         "schema");
  test::expectInputError([] { runMetricsFromJson(R"({"schema": "semslam.metrics/1", "ate_rmse": "x"})", "m.json"); },
                         "m.json", 0, "ate_rmse");
  test::expectInputError([] { runMetricsFromJson(R"({"schema": "semslam.metrics/1", "da_total": 2.5})", "m.json"); },
                         "m.json", 0, "da_total");
  test::expectInputError([] { runMetricsFromJson(R"({"schema": "semslam.metrics/1", "method": 3})", "m.json"); },
                         "m.json", 0, "method");
  test::expectInputError([] { runMetricsFromJson("[1, 2]", "m.json"); }, "m.json", 0, "object");
  test::expectInputError([] { runMetricsFromJson("{", "m.json"); }, "m.json", 0, "JSON");
  test::expectInputError([] { readRunMetrics("/nonexistent/metrics.json"); }, "/nonexistent/metrics.json", 0);
}

// ---- evaluateRun on a hand-made log --------------------------------------------------------------------------

Detection detection(std::optional<int> truthId) {
  Detection d;
  d.geometry = Vector2(1.0, 0.0);
  d.covariance = Matrix2::Identity();
  d.truthId = truthId;
  return d;
}

MeasurementLog smallLog() {
  MeasurementLog log;
  log.header.dimension = 2;
  log.header.classes = 2;
  log.header.landmarkTruth = {{0, 0, Point2(5.0, 0.0)}, {1, 1, Point2(0.0, 5.0)}, {2, 0, Point2(10.0, 10.0)}};
  for (int i = 0; i < 4; ++i) {
    TimeStep step;
    step.time = i;
    step.truePose = SE2(i, 0.5 * i * i, 0.1 * i);
    log.steps.push_back(step);
  }
  log.steps[0].detections = {detection(0), detection(kNotALandmark)};
  log.steps[1].detections = {detection(1)};
  log.steps[2].detections = {detection(0), detection(1)};
  log.steps[3].detections = {detection(std::nullopt)};
  return log;
}

TEST(RunEvaluation, EndToEndOnASmallLog) {
  const MeasurementLog log = smallLog();
  const SE2 frame(1.0, 2.0, 0.3);  // the estimate's frame differs from the truth's by a rigid motion
  RunResult result;
  result.method = "hybrid";
  for (const TimeStep& step : log.steps) {
    result.poses.push_back(frame * std::get<SE2>(*step.truePose));
    result.poseCovariances.push_back(Matrix3::Identity() * 0.01);
  }
  result.associations = {{7, std::nullopt}, {8}, {7, 7}, {std::nullopt}};
  result.landmarks = {{7, Point2(frame.transformFrom(Point2(5.0, 0.0))), Vector2(0.9, 0.1)},
                      {8, Point2(frame.transformFrom(Point2(0.0, 5.0))), Vector2(0.8, 0.2)}};
  HypothesisComponent heavy, light;
  heavy.weight = 3.0;
  heavy.associations = {{7, -1}, {8}, {7, 7}, {-1}};
  heavy.pose = SE2(3.0, 4.5, 0.3);
  heavy.covariance = Matrix3::Identity() * 0.04;
  light.weight = 1.0;
  light.associations = {{8, -1}, {7}, {8, 8}, {-1}};
  light.pose = SE2(3.0, 5.5, 0.3);
  light.covariance = Matrix3::Identity();
  result.components = {heavy, light};
  result.heaviestAssociationWeights = {0.5, 0.95, 0.99, 1.0};
  result.timeSeconds = 1.5;

  const RunEvaluation evaluation = evaluateRun(log, result);
  const RunMetrics& m = evaluation.metrics;
  EXPECT_EQ(m.method, "hybrid");
  EXPECT_EQ(m.dimension, 2);
  EXPECT_EQ(m.timeSeconds, 1.5);
  EXPECT_EQ(m.alignment, "se2");
  EXPECT_EQ(m.poses, 4);
  EXPECT_LT(m.ateMax, 1e-12);
  EXPECT_LT(m.rotMax, 1e-12);
  // 7 ↔ 0 (2 shared), 8 ↔ 1 (1); correct: 0→7, clutter→null, 1→8, 0→7; wrong: 1→7. Step 3 has no truth.
  EXPECT_EQ(m.daTotal, 5);
  EXPECT_EQ(m.daCorrect, 4);
  EXPECT_EQ(m.daNull, 1);
  EXPECT_EQ(m.daClutter, 1);
  EXPECT_DOUBLE_EQ(m.daAccuracy, 0.8);
  // Landmark 2 was never detected nor given as a prior: the method could not know it.
  EXPECT_EQ(m.landmarksEstimated, 2);
  EXPECT_EQ(m.landmarksTrue, 2);
  EXPECT_EQ(m.landmarkCountError, 0);
  EXPECT_EQ(m.landmarksMatched, 2);
  EXPECT_LT(m.landmarkRmse, 1e-12);  // the trajectory's alignment maps the map back too
  EXPECT_DOUBLE_EQ(m.classAccuracy, 0.5);
  // NEES of the unaligned poses.
  EXPECT_EQ(m.neesCount, 4);
  EXPECT_EQ(m.neesDof, 3);
  EXPECT_GT(m.neesMean, 100.0);
  EXPECT_FALSE(evaluation.nees->withinBand());
  // Hybrid: two histories 0.75 / 0.25; true last pose (3, 4.5).
  EXPECT_NEAR(m.entropy, -(0.75 * std::log(0.75) + 0.25 * std::log(0.25)), 1e-14);
  EXPECT_NEAR(m.ess, 1.0 / (0.75 * 0.75 + 0.25 * 0.25), 1e-14);
  EXPECT_NEAR(m.detCov, 0.04 * 0.04, 1e-17);
  EXPECT_NEAR(m.errWmax, 0.0, 1e-15);
  EXPECT_NEAR(m.errWavg, 0.25, 1e-15);
  EXPECT_NEAR(m.assocWeightMax, 0.75, 1e-15);
  EXPECT_DOUBLE_EQ(m.disambiguatedFraction, 0.75);
  EXPECT_EQ(m.components, 2);
  EXPECT_EQ(m.histories, 2);

  // And through the file.
  TempFile file("", ".json");
  writeRunMetrics(file.path(), m);
  EXPECT_EQ(runMetricsToJson(readRunMetrics(file.path())), runMetricsToJson(m));
}

TEST(RunEvaluation, UnknownTruthChangesNoMetric) {
  // The same log and result, plus detections whose truth is "unknown" (docs/metrics.md) on an estimated landmark,
  // on another one and on the null hypothesis, in a step with other detections and in one without: every metric
  // is the same, to the byte of its JSON.
  const MeasurementLog log = smallLog();
  RunResult result;
  result.method = "mm-nh";
  for (const TimeStep& step : log.steps) {
    result.poses.push_back(std::get<SE2>(*step.truePose));
    result.poseCovariances.push_back(Matrix3::Identity() * 0.01);
  }
  result.associations = {{7, std::nullopt}, {8}, {7, 7}, {std::nullopt}};
  result.landmarks = {{7, Point2(5.0, 0.0), Vector2(0.9, 0.1)}, {8, Point2(0.0, 5.0), Vector2(0.8, 0.2)}};
  result.timeSeconds = 0.5;

  MeasurementLog withUnknown = log;
  RunResult resultWithUnknown = result;
  withUnknown.steps[1].detections.push_back(detection(kUnknownTruth));
  resultWithUnknown.associations[1].push_back(7);
  withUnknown.steps[2].detections.push_back(detection(kUnknownTruth));
  resultWithUnknown.associations[2].push_back(8);
  withUnknown.steps[3].detections.push_back(detection(kUnknownTruth));
  resultWithUnknown.associations[3].push_back(std::nullopt);

  const RunMetrics m = evaluateRun(log, result).metrics;
  EXPECT_EQ(m.daTotal, 5);
  EXPECT_EQ(runMetricsToJson(evaluateRun(withUnknown, resultWithUnknown).metrics), runMetricsToJson(m));

  // A log whose only truth is "unknown" scores like a log without detection truth.
  MeasurementLog onlyUnknown = log;
  MeasurementLog noTruth = log;
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    for (std::size_t i = 0; i < log.steps[k].detections.size(); ++i) {
      onlyUnknown.steps[k].detections[i].truthId = kUnknownTruth;
      noTruth.steps[k].detections[i].truthId.reset();
    }
  }
  EXPECT_EQ(runMetricsToJson(evaluateRun(onlyUnknown, result).metrics),
            runMetricsToJson(evaluateRun(noTruth, result).metrics));
}

TEST(RunEvaluation, ClutterSplitsByItsSource) {
  // smallLog's clutter (step 0, no source: a false positive, rejected) plus two detections of a moving object
  // (clutter_source 5) in step 1, one rejected and one put on landmark 8.
  MeasurementLog log = smallLog();
  for (int i = 0; i < 2; ++i) {
    Detection moving = detection(kNotALandmark);
    moving.clutterSource = 5;
    log.steps[1].detections.push_back(moving);
  }
  RunResult result;
  result.method = "mm-nh";
  for (const TimeStep& step : log.steps) result.poses.push_back(std::get<SE2>(*step.truePose));
  result.associations = {{7, std::nullopt}, {8, std::nullopt, 8}, {7, 7}, {std::nullopt}};
  result.landmarks = {{7, Point2(5.0, 0.0), Vector2(0.9, 0.1)}, {8, Point2(0.0, 5.0), Vector2(0.8, 0.2)}};
  const RunMetrics m = evaluateRun(log, result).metrics;
  EXPECT_EQ(m.daClutter, 3);
  EXPECT_DOUBLE_EQ(m.clutterRejected, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.clutterRejectedMoving, 0.5);
  EXPECT_DOUBLE_EQ(m.clutterRejectedFalsePositive, 1.0);
  const Json json = Json::parse(runMetricsToJson(m));
  EXPECT_DOUBLE_EQ(json["clutter_rejected_moving"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(json["clutter_rejected_false_positive"].get<double>(), 1.0);

  // Without the sources (an old log), every clutter detection is a false positive and the moving share is null.
  for (Detection& d : log.steps[1].detections) d.clutterSource.reset();
  const RunMetrics old = evaluateRun(log, result).metrics;
  EXPECT_DOUBLE_EQ(old.clutterRejectedFalsePositive, 2.0 / 3.0);
  EXPECT_TRUE(std::isnan(old.clutterRejectedMoving));
  EXPECT_TRUE(Json::parse(runMetricsToJson(old))["clutter_rejected_moving"].is_null());
}

TEST(RunMetrics, AFileWithoutTheClutterSplitReadsAsNull) {
  // metrics.json written before the split (no clutter_rejected_moving / _false_positive keys) still reads.
  const RunMetrics m = runMetricsFromJson(R"({"schema": "semslam.metrics/1", "clutter_rejected": 0.5})");
  EXPECT_EQ(m.clutterRejected, 0.5);
  EXPECT_TRUE(std::isnan(m.clutterRejectedMoving));
  EXPECT_TRUE(std::isnan(m.clutterRejectedFalsePositive));
}

TEST(RunEvaluation, MaxMarginalMethodWithoutHybridFields) {
  const MeasurementLog log = smallLog();
  RunResult result;
  result.method = "ml";
  for (const TimeStep& step : log.steps) result.poses.push_back(*step.truePose);
  const RunMetrics m = evaluateRun(log, result).metrics;
  EXPECT_EQ(m.ateMax, 0.0);
  EXPECT_TRUE(std::isnan(m.daAccuracy));  // no associations reported
  EXPECT_FALSE(m.daTotal);
  EXPECT_TRUE(std::isnan(m.neesMean));
  EXPECT_FALSE(m.neesCount);
  EXPECT_TRUE(std::isnan(m.entropy));
  EXPECT_TRUE(std::isnan(m.ess));
  EXPECT_TRUE(std::isnan(m.timeSeconds));
  EXPECT_EQ(m.landmarksEstimated, 0);
  EXPECT_EQ(m.landmarksTrue, 2);
  EXPECT_FALSE(m.landmarksMatched);
  const Json json = Json::parse(runMetricsToJson(m));
  EXPECT_TRUE(json["entropy"].is_null());
  EXPECT_TRUE(json["da_accuracy"].is_null());
}

TEST(RunEvaluation, StationaryRobotFallsBackToNoAlignment) {
  MeasurementLog log = smallLog();
  for (TimeStep& step : log.steps) step.truePose = SE2(1.0, 1.0, 0.0);
  RunResult result;
  for (std::size_t i = 0; i < log.steps.size(); ++i) result.poses.push_back(SE2(1.0, 2.0, 0.0));
  const RunMetrics m = evaluateRun(log, result).metrics;
  EXPECT_EQ(m.alignment, "none");
  EXPECT_DOUBLE_EQ(m.ateRmse, 1.0);
}

TEST(RunEvaluation, SizesMustFitTheLog) {
  const MeasurementLog log = smallLog();
  RunResult tooFewPoses;
  tooFewPoses.poses = {SE2()};
  EXPECT_THROW(evaluateRun(log, tooFewPoses), InputError);
  RunResult wrongDetections;
  wrongDetections.associations = {{1}, {1}, {1, 1}, {}};
  EXPECT_THROW(evaluateRun(log, wrongDetections), InputError);
}

}  // namespace
}  // namespace semslam
