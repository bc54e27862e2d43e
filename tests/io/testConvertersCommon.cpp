// The pieces every converter shares, on small synthetic logs: keyframing, class labels, option checks, residual
// statistics; and a converter's errors on a hand-written Lost in the Woods folder.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>

#include "../../fuzz/ConverterReaders.h"
#include "io/ConverterTesting.h"
#include "semslam/eval/MeasurementResiduals.h"
#include "semslam/io/convert/ClassLabels.h"
#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/io/convert/Keyframing.h"
#include "semslam/io/convert/LostInTheWoodsConverter.h"
#include "semslam/models/CategoricalClassifierModel.h"
#include "semslam/models/OdometryComposition.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/UnicycleModel.h"

using namespace semslam;
using semslam::test::TempDir;

namespace {

Detection detectionOf(int truth) {
  Detection d;
  d.geometry = Vector2(1.0, 0.0);
  d.covariance = Matrix::Identity(2, 2) * 0.01;
  d.truthId = truth;
  return d;
}

// Steps at 0, 0.25, 0.5, ... with unicycle odometry and detections at the listed steps.
std::vector<TimeStep> syntheticSteps(std::size_t n, const std::vector<std::size_t>& withDetections) {
  const UnicycleModel model(0.01, 0.02);
  std::vector<TimeStep> steps(n);
  for (std::size_t k = 0; k < n; ++k) {
    steps[k].time = 0.25 * static_cast<double>(k);
    if (k > 0) steps[k].odometry = model.integrate(1.0 + 0.1 * static_cast<double>(k), 0.3, 0.25);
    steps[k].truePose = SE2(static_cast<double>(k), 0.0, 0.0);
  }
  for (std::size_t k : withDetections) steps.at(k).detections.push_back(detectionOf(static_cast<int>(k)));
  return steps;
}

}  // namespace

TEST(Keyframing, OneStepPerSlotPreferringStepsWithDetections) {
  // Slots of 1 s hold steps {0..3}, {4..7}, {8..9}; detections at 2, 3, 9.
  const std::vector<TimeStep> steps = syntheticSteps(10, {2, 3, 9});
  KeyframeSummary summary;
  const std::vector<TimeStep> kept = selectKeyframes(steps, 1.0, &summary);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0].time, 0.5);   // the first step of slot 0 with detections
  EXPECT_EQ(kept[1].time, 1.0);   // slot 1 has none: its first step
  EXPECT_EQ(kept[2].time, 2.25);  // slot 2: step 9
  EXPECT_EQ(summary.keptSteps, 3u);
  EXPECT_EQ(summary.droppedSteps, 7u);
  EXPECT_EQ(summary.droppedDetections, 1u);  // step 3's
  EXPECT_FALSE(kept[0].odometry.has_value());
  EXPECT_TRUE(test::samePose(*kept[1].truePose, *steps[4].truePose));
  // Keyframe 1 composes the increments of steps 3 and 4, keyframe 2 those of 5..9.
  const Odometry expected1 = composeOdometry(*steps[3].odometry, *steps[4].odometry);
  EXPECT_TRUE(std::get<SE2>(kept[1].odometry->increment).equals(std::get<SE2>(expected1.increment), 1e-15));
  EXPECT_EQ(kept[1].odometry->covariance, expected1.covariance);
  Odometry expected2 = *steps[5].odometry;
  for (std::size_t k = 6; k <= 9; ++k) expected2 = composeOdometry(expected2, *steps[k].odometry);
  EXPECT_TRUE(std::get<SE2>(kept[2].odometry->increment).equals(std::get<SE2>(expected2.increment), 1e-15));
}

TEST(Keyframing, PeriodShorterThanTheStepsKeepsEverything) {
  const std::vector<TimeStep> steps = syntheticSteps(6, {1, 4});
  KeyframeSummary summary;
  const std::vector<TimeStep> kept = selectKeyframes(steps, 0.1, &summary);
  ASSERT_EQ(kept.size(), 6u);
  EXPECT_EQ(summary.droppedSteps, 0u);
  for (std::size_t k = 1; k < 6; ++k) EXPECT_EQ(kept[k].odometry->covariance, steps[k].odometry->covariance);
  EXPECT_THROW(selectKeyframes(steps, 0.0), std::invalid_argument);
  EXPECT_THROW(selectKeyframes(steps, std::nan("")), std::invalid_argument);
}

TEST(Keyframing, KeepFirstSteps) {
  std::vector<TimeStep> steps = syntheticSteps(6, {1, 4, 5});
  EXPECT_EQ(keepFirstSteps(steps, 0), 0u);
  EXPECT_EQ(steps.size(), 6u);
  EXPECT_EQ(keepFirstSteps(steps, 4), 2u);
  EXPECT_EQ(steps.size(), 4u);
  EXPECT_EQ(keepFirstSteps(steps, 10), 0u);
}

TEST(ClassLabels, OneClassMeansNoSemanticPart) {
  MeasurementLog log;
  log.steps = syntheticSteps(3, {0, 1, 2});
  log.header.landmarkTruth = {LandmarkTruth{5, -1, Point2(1.0, 2.0)}};
  assignClassLabels(log, 1, 0.0, 1);
  EXPECT_EQ(log.header.semantic, SemanticKind::None);
  EXPECT_EQ(log.header.classifier.kind, ClassifierModelSpec::Kind::None);
  EXPECT_EQ(log.header.landmarkTruth[0].classIndex, 0);
  for (const TimeStep& step : log.steps) EXPECT_FALSE(step.detections[0].label.has_value());
  EXPECT_THROW(assignClassLabels(log, 1, 0.1, 1), std::invalid_argument);
  EXPECT_THROW(assignClassLabels(log, 0, 0.0, 1), std::invalid_argument);
}

TEST(ClassLabels, LabelsFollowTheConfusionModelInAFixedOrder) {
  MeasurementLog log;
  for (int k = 0; k < 4000; ++k) {
    TimeStep step;
    step.time = k;
    step.detections.push_back(detectionOf(k % 7));
    step.detections.push_back(detectionOf(kNotALandmark));
    log.steps.push_back(step);
  }
  for (int id = 0; id < 7; ++id) log.header.landmarkTruth.push_back(LandmarkTruth{id, -1, Point2(0.0, 0.0)});
  MeasurementLog again = log;
  assignClassLabels(log, 3, 0.0, 17);
  assignClassLabels(again, 3, 0.0, 17);
  EXPECT_EQ(log.header.semantic, SemanticKind::Label);
  EXPECT_EQ(log.header.landmarkTruth[5].classIndex, 2);
  std::vector<int> clutterCounts(3, 0);
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    // p = 0: every landmark label is its class; clutter labels are uniform.
    EXPECT_EQ(*log.steps[k].detections[0].label, static_cast<int>(k % 7) % 3);
    ++clutterCounts.at(static_cast<std::size_t>(*log.steps[k].detections[1].label));
    EXPECT_EQ(log.steps[k].detections[1].label, again.steps[k].detections[1].label);
  }
  for (int count : clutterCounts) EXPECT_NEAR(count, 4000.0 / 3.0, 4.0 * std::sqrt(4000.0 * 2.0 / 9.0));
  // The draws are the model's own, in step and detection order, two engine outputs each.
  std::mt19937 rng(17);
  const CategoricalClassifierModel model(3, 0.0);
  EXPECT_EQ(*log.steps[0].detections[0].label, model.sampleLabel(0, rng));
  EXPECT_EQ(*log.steps[0].detections[1].label, static_cast<int>(uniform01(rng) * 3));
}

TEST(ConvertOptions, RejectsOutOfRangeSettings) {
  ConvertOptions options;
  EXPECT_NO_THROW(validateConvertOptions(options, 2));
  options.classes = 0;
  EXPECT_THROW(validateConvertOptions(options, 2), InputError);
  options = ConvertOptions{};
  options.misclassification = 0.2;  // needs two classes
  EXPECT_THROW(validateConvertOptions(options, 2), InputError);
  options.classes = 2;
  EXPECT_NO_THROW(validateConvertOptions(options, 2));
  options.misclassification = 1.0;
  EXPECT_THROW(validateConvertOptions(options, 2), InputError);
  options = ConvertOptions{};
  options.initialPoseSigmas = {0.1, 0.1, 0.1};
  EXPECT_NO_THROW(validateConvertOptions(options, 2));
  EXPECT_THROW(validateConvertOptions(options, 3), InputError);  // 3D needs six
  options.initialPoseSigmas = {0.1, 0.0, 0.1};
  EXPECT_THROW(validateConvertOptions(options, 2), InputError);
  // Each sigma in [1e-9, 1e9], but the prior's condition number at most 1e12 (io/InputMagnitudes.h).
  options.initialPoseSigmas = {1e-3, 1e3, 1e-3};
  EXPECT_NO_THROW(validateConvertOptions(options, 2));
  options.initialPoseSigmas = {1e-4, 1e3, 1e-3};
  EXPECT_THROW(validateConvertOptions(options, 2), InputError);
  options = ConvertOptions{};
  options.keyframePeriod = -1.0;
  EXPECT_THROW(validateConvertOptions(options, 2), InputError);
  options = ConvertOptions{};
  options.mapPriorSigma = std::nan("");
  EXPECT_THROW(validateConvertOptions(options, 2), InputError);
}

TEST(MeasurementResiduals, ExactMeasurementsHaveZeroResidualsAndOffsetsShow) {
  MeasurementLog log;
  log.header.sensor.kind = SensorKind::RangeBearing;
  log.header.sensor.bodyToSensor = SE2(0.2, 0.0, 0.0);
  log.header.landmarkTruth = {LandmarkTruth{3, 0, Point2(4.0, 1.0)}};
  const RangeBearingSensor2 sensor(SE2(0.2, 0.0, 0.0));
  const UnicycleModel model(0.01, 0.01);
  SE2 pose;
  for (int k = 0; k < 20; ++k) {
    TimeStep step;
    step.time = k;
    if (k > 0) {
      step.odometry = model.integrate(0.5, 0.1, 1.0);
      pose = pose * std::get<SE2>(step.odometry->increment);
    }
    step.truePose = pose;
    Detection detection = detectionOf(3);
    detection.geometry = sensor.predict(pose, Point2(4.0, 1.0)) + Vector2(0.0, 0.01);  // a bearing offset
    step.detections.push_back(detection);
    step.detections.push_back(detectionOf(kNotALandmark));
    log.steps.push_back(step);
  }
  const LogResidualStatistics residuals = computeResidualStatistics(log);
  EXPECT_EQ(residuals.detectionsEvaluated, 20u);
  EXPECT_EQ(residuals.detectionsClutter, 20u);
  ASSERT_EQ(residuals.detection.size(), 2u);
  EXPECT_NEAR(residuals.detection[0].mean, 0.0, 1e-12);
  EXPECT_NEAR(residuals.detection[1].mean, 0.01, 1e-12);
  EXPECT_NEAR(residuals.detection[1].std, 0.0, 1e-12);
  EXPECT_NEAR(residuals.detection[1].statedStd, 0.1, 1e-12);
  EXPECT_EQ(residuals.odometryEvaluated, 19u);
  for (const auto& c : residuals.odometry) EXPECT_NEAR(c.std, 0.0, 1e-12);
  const std::string text = formatResidualStatistics(residuals);
  EXPECT_NE(text.find("bearing"), std::string::npos);
  EXPECT_NE(text.find("theta"), std::string::npos);
}

TEST(LostInTheWoodsConverter, ErrorsNameTheFileAndLine) {
  TempDir dir;
  dir.write("params.txt", "d 0.2\nr_var 0.01\nb_var 0.01\nv_var 0.01\nom_var 0.01\n");
  dir.write("odometry.txt", "# t v omega\n0.0 0.1 0.0\n0.1 0.1 0.0\n");
  dir.write("groundtruth.txt", "0.0 0 0 0 1\n0.1 0.01 0 0 0\n");
  dir.write("landmarks_groundtruth.txt", "1 2.0 0.5\n");
  const std::string folder = dir.path("");
  const std::string measurements = dir.write("measurements.txt", "0.0 1 1.8 0.3\n0.15 1 1.7 0.3\n");
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), measurements, 2, "matches no odometry");
  dir.write("measurements.txt", "0.0 1 1.8 0.3\n0.1 2 1.7 0.3\n");
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), measurements, 2, "landmark id 2");
  dir.write("measurements.txt", "0.0 1 1.8\n");
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), measurements, 1, "expected 4 numbers");
  dir.write("measurements.txt", "0.0 1 1.8 0.3\n0.1 1 1.7 0.3\n");
  const MeasurementLog log = convertLostInTheWoods(folder, ConvertOptions{});
  ASSERT_EQ(log.steps.size(), 2u);
  EXPECT_TRUE(log.steps[0].truePose.has_value());
  EXPECT_FALSE(log.steps[1].truePose.has_value());  // valid = 0
  EXPECT_EQ(log.steps[1].detections.size(), 1u);
}

// Every converter error names the dataset file and the line that caused it, as the readers do (issue 16: numbers a
// log may not hold were reported by the log's step, or at the folder). Over every converter input kept in the fuzz
// corpus and findings (fuzz/README.md), each refusal names one of the files the converter reads, and a line unless
// the problem is of that file as a whole (absent, without data rows, or lacking a named parameter).
TEST(ConverterErrors, EveryCorpusInputIsRefusedAtAFileAndLine) {
  namespace fs = std::filesystem;
  const std::map<std::string, std::string> kinds = {{"convert-isam", "isam"},
                                                    {"convert-litw", "utias-lost-in-the-woods"},
                                                    {"convert-starry-night", "utias-starry-night"},
                                                    {"convert-mrclam", "mrclam"},
                                                    {"convert-kitti-tracking", "kitti-tracking"}};
  const auto wholeFile = [](const std::string& problem) {
    for (const char* kind : {"file does not exist", "no data rows", "missing parameter", "missing entry"}) {
      if (problem.find(kind) != std::string::npos) return true;
    }
    return false;
  };
  std::size_t refused = 0, atALine = 0;
  for (const auto& [harness, kind] : kinds) {
    for (const char* root : {"corpus", "findings"}) {
      const fs::path folder = fs::path(SEMSLAM_SOURCE_DIR) / "fuzz" / root / harness;
      if (!fs::is_directory(folder)) continue;
      for (const fs::directory_entry& input : fs::directory_iterator(folder)) {
        try {
          semslam::fuzz::convertPacked(kind, input.path().string());
        } catch (const InputError& error) {
          ++refused;
          const std::string where = harness + "/" + input.path().filename().string() + ": " + error.what();
          bool named = false;
          for (const std::string& file : semslam::fuzz::converterFiles(kind)) {
            const std::string path = error.file();
            named = named || (path.size() >= file.size() && path.compare(path.size() - file.size(), file.size(), file) == 0);
          }
          EXPECT_TRUE(named) << where;
          if (error.line() > 0) {
            ++atALine;
          } else {
            EXPECT_TRUE(wholeFile(error.problem())) << where;
          }
        }
      }
    }
  }
  // The corpus holds inputs of each kind (fuzz/README.md): not a vacuous pass.
  EXPECT_GE(refused, 15u);
  EXPECT_GE(atALine, 12u);
}
