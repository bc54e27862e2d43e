// `semslam convert utias-lost-in-the-woods`: counts against the raw files, round trip through the log reader,
// determinism, labels, keyframing, truncation and the residuals against the stated noise.

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "io/ConverterTesting.h"
#include "semslam/eval/MeasurementResiduals.h"
#include "semslam/io/convert/LostInTheWoodsConverter.h"
#include "semslam/models/OdometryComposition.h"
#include "semslam/models/UnicycleModel.h"
#include "support/TestData.h"

using namespace semslam;
using semslam::test::rawRows;
using semslam::test::TempDir;

namespace {

constexpr const char* kFolder = "utias-lost-in-the-woods";

std::map<std::string, double> rawParams(const std::filesystem::path& folder) {
  std::map<std::string, double> params;
  std::ifstream in(folder / "params.txt");
  std::string name;
  double value = 0.0;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    if (line.empty() || line[0] == '#') continue;
    if (fields >> name >> value) params[name] = value;
  }
  return params;
}

}  // namespace

TEST(LostInTheWoodsConverter, CountsMatchTheDatasetAndTheLogReadsBack) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  // (No time limit here: a timing assert fails on a loaded machine and under the sanitizers, 19 s in make sanitize.)
  ConversionStats stats;
  const MeasurementLog log = convertLostInTheWoods(folder.string(), ConvertOptions{}, &stats);

  // The figures of SOURCE.txt and the brief, and the raw files counted here.
  EXPECT_EQ(log.steps.size(), 12609u);
  EXPECT_EQ(test::detectionCount(log), 61086u);
  EXPECT_EQ(log.steps.size(), rawRows((folder / "odometry.txt").string()).size());
  const auto measurements = rawRows((folder / "measurements.txt").string());
  EXPECT_EQ(test::detectionCount(log), measurements.size());
  std::size_t valid = 0;
  for (const auto& row : rawRows((folder / "groundtruth.txt").string())) valid += row.at(4) == 1.0 ? 1 : 0;
  std::size_t truePoses = 0;
  for (const TimeStep& step : log.steps) truePoses += step.truePose ? 1 : 0;
  EXPECT_EQ(truePoses, valid);
  EXPECT_EQ(log.header.landmarkTruth.size(), 17u);
  EXPECT_EQ(stats.steps, 12609u);
  EXPECT_EQ(stats.detections, 61086u);
  EXPECT_EQ(stats.detectionsDroppedByKeyframing, 0u);

  // Per landmark, the detections' truth ids count as the raw rows' ids do.
  std::map<int, std::size_t> rawPerId, logPerId;
  for (const auto& row : measurements) ++rawPerId[static_cast<int>(row.at(1))];
  for (const TimeStep& step : log.steps) {
    for (const Detection& detection : step.detections) ++logPerId[detection.truthId.value()];
  }
  EXPECT_EQ(rawPerId, logPerId);

  // Header: range-bearing from the laser d ahead of the centre, no semantics with one class.
  EXPECT_EQ(log.header.dimension, 2);
  EXPECT_EQ(log.header.sensor.kind, SensorKind::RangeBearing);
  EXPECT_DOUBLE_EQ(std::get<SE2>(log.header.sensor.bodyToSensor).x(), rawParams(folder)["d"]);
  EXPECT_EQ(log.header.semantic, SemanticKind::None);
  ASSERT_TRUE(log.header.initialPose.has_value());
  EXPECT_TRUE(test::samePose(log.header.initialPose->mean, *log.steps.front().truePose));

  TempDir dir;
  MeasurementLog back;
  test::writeAndReadBack(log, dir, "litw.jsonl", &back);
  EXPECT_EQ(back.steps.size(), 12609u);
  EXPECT_EQ(test::detectionCount(back), 61086u);
}

TEST(LostInTheWoodsConverter, SameSeedSameBytesOtherSeedOtherLabelsOnly) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  ConvertOptions options;
  options.classes = 3;
  options.misclassification = 0.2;
  options.seed = 11;
  TempDir dir;
  const std::string first = test::writeAndReadBack(convertLostInTheWoods(folder.string(), options), dir, "a.jsonl");
  const std::string second = test::writeAndReadBack(convertLostInTheWoods(folder.string(), options), dir, "b.jsonl");
  EXPECT_TRUE(first == second) << "two runs with the same seed differ";

  const MeasurementLog a = convertLostInTheWoods(folder.string(), options);
  options.seed = 12;
  const MeasurementLog b = convertLostInTheWoods(folder.string(), options);
  const std::size_t different = test::expectSameExceptLabels(a, b);
  // Two independent draws disagree with probability 1 - (0.8² + 2 · 0.1²) = 0.34.
  EXPECT_GT(different, 61086u / 4);
  EXPECT_LT(different, 61086u / 2);
}

TEST(LostInTheWoodsConverter, MisclassificationRateWithinItsBinomialInterval) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  for (const double p : {0.0, 0.1, 0.3}) {
    ConvertOptions options;
    options.classes = 4;
    options.misclassification = p;
    options.seed = 5;
    const MeasurementLog log = convertLostInTheWoods(folder.string(), options);
    EXPECT_EQ(log.header.semantic, SemanticKind::Label);
    EXPECT_EQ(log.header.classifier.kind, ClassifierModelSpec::Kind::Categorical);
    EXPECT_EQ(log.header.classifier.misclassification, p);
    for (const LandmarkTruth& truth : log.header.landmarkTruth) EXPECT_EQ(truth.classIndex, truth.id % 4);
    std::size_t wrong = 0, n = 0;
    std::map<int, std::size_t> wrongLabels;
    for (const TimeStep& step : log.steps) {
      for (const Detection& detection : step.detections) {
        ++n;
        const int truthClass = *detection.truthId % 4;
        if (*detection.label != truthClass) {
          ++wrong;
          ++wrongLabels[(*detection.label - truthClass + 4) % 4];
        }
      }
    }
    const double rate = static_cast<double>(wrong) / static_cast<double>(n);
    const double sigma = std::sqrt(p * (1.0 - p) / static_cast<double>(n));
    EXPECT_NEAR(rate, p, 4.0 * sigma + 1e-12) << "p = " << p;  // a 4-sigma binomial interval
    // The wrong labels spread evenly over the other three classes.
    for (const auto& [offset, count] : wrongLabels) {
      const double share = static_cast<double>(count) / static_cast<double>(wrong);
      EXPECT_NEAR(share, 1.0 / 3.0, 4.0 * std::sqrt(2.0 / 9.0 / static_cast<double>(wrong))) << offset;
    }
  }
}

TEST(LostInTheWoodsConverter, KeyframesAtOneSecondComposeTheUnicycleIncrements) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  ConvertOptions options;
  options.keyframePeriod = 1.0;
  ConversionStats stats;
  const MeasurementLog log = convertLostInTheWoods(folder.string(), options, &stats);
  // 0 .. 1260.8 s at 10 Hz: one keyframe in each of the seconds 0 .. 1260.
  EXPECT_EQ(log.steps.size(), 1261u);
  EXPECT_EQ(stats.stepsDroppedByKeyframing, 12609u - 1261u);
  EXPECT_EQ(stats.detectionsDroppedByKeyframing + test::detectionCount(log), 61086u);
  EXPECT_FALSE(log.steps.front().odometry.has_value());

  const auto odometry = rawRows((folder / "odometry.txt").string());
  const auto params = rawParams(folder);
  const UnicycleModel model(params.at("v_var"), params.at("om_var"));
  std::size_t previous = 0;  // the raw row of the previous keyframe
  std::size_t checked = 0;
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    const TimeStep& step = log.steps[k];
    EXPECT_EQ(std::floor(step.time + 1e-9), static_cast<double>(k)) << "one keyframe per second";
    // The raw row of this keyframe.
    std::size_t row = previous;
    while (row < odometry.size() && std::abs(odometry[row][0] - step.time) > 1e-9) ++row;
    ASSERT_LT(row, odometry.size());
    if (k > 0) {
      ASSERT_TRUE(step.odometry.has_value());
      SE2 chained;
      Odometry composed = identityOdometry(2);
      for (std::size_t i = previous + 1; i <= row; ++i) {
        const double dt = odometry[i][0] - odometry[i - 1][0];
        chained = chained * UnicycleModel::increment(odometry[i - 1][1], odometry[i - 1][2], dt);
        composed = composeOdometry(composed, model.integrate(odometry[i - 1][1], odometry[i - 1][2], dt));
      }
      const SE2& increment = std::get<SE2>(step.odometry->increment);
      EXPECT_TRUE(increment.equals(chained, 1e-12)) << "keyframe " << k;
      EXPECT_LT((step.odometry->covariance - composed.covariance).cwiseAbs().maxCoeff(), 1e-15) << "keyframe " << k;
      ++checked;
    }
    previous = row;
  }
  EXPECT_EQ(checked, 1260u);
  TempDir dir;
  test::writeAndReadBack(log, dir, "keyframes.jsonl");
}

TEST(LostInTheWoodsConverter, MaxStepsKeepsTheFirstSteps) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  ConvertOptions options;
  options.classes = 3;
  options.misclassification = 0.1;
  const MeasurementLog full = convertLostInTheWoods(folder.string(), options);
  options.maxSteps = 250;
  ConversionStats stats;
  MeasurementLog head = convertLostInTheWoods(folder.string(), options, &stats);
  ASSERT_EQ(head.steps.size(), 250u);
  EXPECT_EQ(stats.stepsDroppedByMaxSteps, 12609u - 250u);
  // The first 250 steps of the full log, labels included.
  MeasurementLog prefix = full;
  prefix.steps.resize(250);
  EXPECT_EQ(test::expectSameExceptLabels(prefix, head), 0u);
  EXPECT_EQ(stats.detections + stats.detectionsDroppedByMaxSteps, 61086u);

  // With keyframing, --max-steps counts keyframes.
  options.keyframePeriod = 1.0;
  options.maxSteps = 100;
  const MeasurementLog keyframes = convertLostInTheWoods(folder.string(), options);
  EXPECT_EQ(keyframes.steps.size(), 100u);
  EXPECT_NEAR(keyframes.steps.back().time, 99.0, 0.95);
}

TEST(LostInTheWoodsConverter, ResidualsMatchTheStatedMeasurementNoise) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  const MeasurementLog log = convertLostInTheWoods(folder.string(), ConvertOptions{});
  const LogResidualStatistics residuals = computeResidualStatistics(log);
  const auto params = rawParams(folder);
  ASSERT_EQ(residuals.detection.size(), 2u);
  EXPECT_EQ(residuals.detection[0].name, "range");
  EXPECT_EQ(residuals.detectionsEvaluated + residuals.detectionsWithoutTruePose, 61086u);
  // Within 20 % of the stated standard deviations (measured: 0.0327 m vs 0.0300, 0.0255 rad vs 0.0259).
  EXPECT_NEAR(residuals.detection[0].std / std::sqrt(params.at("r_var")), 1.0, 0.2);
  EXPECT_NEAR(residuals.detection[1].std / std::sqrt(params.at("b_var")), 1.0, 0.2);
  EXPECT_NEAR(residuals.detection[0].statedStd, std::sqrt(params.at("r_var")), 1e-12);
  // Per 0.1 s step the forward odometry residual is near its stated std (docs/datasets.md reports the rest).
  ASSERT_EQ(residuals.odometry.size(), 3u);
  EXPECT_NEAR(residuals.odometry[0].std / residuals.odometry[0].statedStd, 1.0, 0.2);
  std::printf("%s", formatResidualStatistics(residuals).c_str());
}

// Numbers a log may not hold are refused at the dataset row that made them, as the readers report their own errors
// (they were reported as "step 3" of the log, or at the folder: issue 16).
TEST(LostInTheWoodsConverter, NumbersALogMayNotHoldAreRefusedAtTheirRow) {
  TempDir dir;
  const std::string folder = dir.path("");
  const std::string params = dir.path("params.txt"), odometry = dir.path("odometry.txt");
  const std::string truth = dir.path("groundtruth.txt"), landmarks = dir.path("landmarks_groundtruth.txt");
  const std::string measurements = dir.path("measurements.txt");
  const auto writeFolder = [&](const std::map<std::string, std::string>& edits) {
    std::map<std::string, std::string> files = {
        {"params.txt", "d 0.2\nr_var 0.01\nb_var 0.01\nv_var 0.01\nom_var 0.01\n"},
        {"odometry.txt", "# t v omega\n0.0 0.1 0.0\n0.5 0.1 0.0\n1.0 0.1 0.0\n"},
        {"groundtruth.txt", "0.0 0 0 0 1\n0.5 0.05 0 0 1\n1.0 0.1 0 0 1\n"},
        {"landmarks_groundtruth.txt", "1 2.0 0.5\n"},
        {"measurements.txt", "0.0 1 1.8 0.3\n0.5 1 1.7 0.3\n"}};
    for (const auto& [name, text] : edits) files[name] = text;
    for (const auto& [name, text] : files) dir.write(name, text);
  };
  writeFolder({});
  EXPECT_EQ(convertLostInTheWoods(folder, ConvertOptions{}).steps.size(), 3u);

  writeFolder({{"measurements.txt", "0.0 1 1.8 0.3\n0.5 1 1e-7 0.3\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), measurements, 2, "the range must be at least");
  // The increment into step 2 integrates row 1's velocities (line 3).
  writeFolder({{"odometry.txt", "# t v omega\n0.0 0.1 0.0\n0.5 1e300 0.0\n1.0 0.1 0.0\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), odometry, 3, "odometry.increment[0]");
  writeFolder({{"groundtruth.txt", "0.0 0 0 0 1\n0.5 2e7 0 0 1\n1.0 0.1 0 0 1\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), truth, 2, "true_pose[0]");
  // The first true pose is also the header's initial pose prior.
  writeFolder({{"groundtruth.txt", "0.0 2e7 0 0 1\n0.5 0.05 0 0 1\n1.0 0.1 0 0 1\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), truth, 1, "initial_pose.mean[0]");
  writeFolder({{"params.txt", "r_var 0.01\nb_var 0.01\nd 2e7\nv_var 0.01\nom_var 0.01\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), params, 3, "sensor.body_to_sensor[0]");
  writeFolder({{"landmarks_groundtruth.txt", "1 2.0 0.5\n2 -2e7 0.5\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), landmarks, 2, "landmark_truth[1].position[0]");
  writeFolder({{"params.txt", "d 0.2\nr_var 1e19\nb_var 0.01\nv_var 0.01\nom_var 0.01\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), params, 2, "'r_var' must be in [1e-18, 1e18]");
  writeFolder({{"params.txt", "d 0.2\nr_var 0.01\nb_var 0\nv_var 0.01\nom_var 0.01\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), params, 3, "'b_var' must be > 0");
  // A ground-truth row short: the odometry row without one.
  writeFolder({{"groundtruth.txt", "0.0 0 0 0 1\n0.5 0.05 0 0 1\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), odometry, 4, "no ground-truth row");
  writeFolder({{"groundtruth.txt", "0.0 0 0 0 1\n0.5 0.05 0 0 1\n1.0 0.1 0 0 1\n1.5 0.1 0 0 1\n"}});
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, ConvertOptions{}), truth, 4, "no odometry row");
}

// Two increments of 6e6 m each are fine on their own; keyframed into one step they make 1.2e7 m, past the log's
// 1e7: refused at the last row composed, naming the range of rows. (A turn-rate variance of 1e-12 keeps the lateral
// variance of a 6e6 m increment, om_var (v dt²/2)², within the log's condition number limit.)
TEST(LostInTheWoodsConverter, AComposedOdometryBeyondTheLimitsNamesTheRowsComposed) {
  TempDir dir;
  const std::string folder = dir.path("");
  dir.write("params.txt", "d 0.2\nr_var 0.01\nb_var 0.01\nv_var 0.01\nom_var 1e-12\n");
  const std::string odometry = dir.write("odometry.txt", "# t v omega\n0.0 1.2e7 0.0\n0.5 1.2e7 0.0\n1.0 0.1 0.0\n");
  dir.write("groundtruth.txt", "0.0 0 0 0 1\n0.5 0 0 0 0\n1.0 0 0 0 0\n");
  dir.write("landmarks_groundtruth.txt", "1 2.0 0.5\n");
  dir.write("measurements.txt", "0.0 1 1.8 0.3\n0.5 1 1.7 0.3\n");
  EXPECT_EQ(convertLostInTheWoods(folder, ConvertOptions{}).steps.size(), 3u);
  ConvertOptions keyframed;
  keyframed.keyframePeriod = 1.0;  // keeps step 0 and step 2, whose odometry composes the rows of lines 2 and 3
  EXPECT_INPUT_ERROR(convertLostInTheWoods(folder, keyframed), odometry, 3,
                     "(the odometry of lines 2 to 3, composed by --keyframe-period)");
}
