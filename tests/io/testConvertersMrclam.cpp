// `semslam convert mrclam`: counts against the raw files (every measurement kept, clutter marked "not a landmark"),
// barcodes mapped to subjects, odometry split at measurement stamps, round trip and determinism.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "io/ConverterTesting.h"
#include "semslam/eval/MeasurementResiduals.h"
#include "semslam/io/convert/MrclamConverter.h"
#include "semslam/models/OdometryComposition.h"
#include "semslam/models/UnicycleModel.h"
#include "support/TestData.h"

using namespace semslam;
using semslam::test::rawRows;
using semslam::test::TempDir;

namespace {

constexpr const char* kFolder = "mrclam/MRCLAM_Dataset6";

struct RawCounts {
  std::size_t steps = 0;
  std::size_t measurements = 0;
  std::size_t clutter = 0;
  std::map<int, std::size_t> perSubject;  // landmark subjects only
};

// Counted from the raw files, independently of the converter.
RawCounts countRaw(const std::filesystem::path& folder, int robot) {
  const std::string name = "Robot" + std::to_string(robot);
  std::map<int, int> subjectOfBarcode;
  for (const auto& row : rawRows((folder / "Barcodes.dat").string())) {
    subjectOfBarcode[static_cast<int>(row[1])] = static_cast<int>(row[0]);
  }
  RawCounts counts;
  std::set<double> times;
  for (const auto& row : rawRows((folder / (name + "_Odometry.dat")).string())) times.insert(row[0]);
  for (const auto& row : rawRows((folder / (name + "_Measurement.dat")).string())) {
    times.insert(row[0]);
    ++counts.measurements;
    const auto it = subjectOfBarcode.find(static_cast<int>(row[1]));
    if (it == subjectOfBarcode.end() || it->second < 6 || it->second > 20) {
      ++counts.clutter;
    } else {
      ++counts.perSubject[it->second];
    }
  }
  counts.steps = times.size();
  return counts;
}

}  // namespace

TEST(MrclamConverter, EveryMeasurementIsKeptAndClutterIsNotALandmark) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  for (int robot = 1; robot <= 5; ++robot) {
    ConvertOptions options;
    options.robot = robot;
    ConversionStats stats;
    const MeasurementLog log = convertMrclam(folder.string(), options, &stats);
    const RawCounts raw = countRaw(folder, robot);
    EXPECT_EQ(log.steps.size(), raw.steps) << "robot " << robot;
    EXPECT_EQ(test::detectionCount(log), raw.measurements) << "robot " << robot;
    EXPECT_EQ(stats.clutter, raw.clutter) << "robot " << robot;
    std::size_t clutter = 0;
    std::map<int, std::size_t> perSubject;
    for (const TimeStep& step : log.steps) {
      for (const Detection& detection : step.detections) {
        ASSERT_TRUE(detection.truthId.has_value());
        if (*detection.truthId == kNotALandmark) {
          ++clutter;
        } else {
          ++perSubject[*detection.truthId];
        }
      }
    }
    EXPECT_EQ(clutter, raw.clutter) << "robot " << robot;
    EXPECT_EQ(perSubject, raw.perSubject) << "robot " << robot;
    EXPECT_EQ(log.header.landmarkTruth.size(), 15u);
    for (const LandmarkTruth& truth : log.header.landmarkTruth) {
      EXPECT_GE(truth.id, 6);
      EXPECT_LE(truth.id, 20);
    }
  }
  // Robot 1 of Dataset 6, as SOURCE.txt describes it: 1,942 measurements, of which 407 are sightings of other
  // robots and 1 an unknown barcode.
  ConversionStats stats;
  const MeasurementLog log = convertMrclam(folder.string(), ConvertOptions{}, &stats);
  EXPECT_EQ(stats.detections, 1942u);
  EXPECT_EQ(stats.clutter, 408u);
  TempDir dir;
  MeasurementLog back;
  test::writeAndReadBack(log, dir, "robot1.jsonl", &back);
  EXPECT_EQ(test::detectionCount(back), 1942u);
  EXPECT_EQ(back.steps.size(), log.steps.size());
}

TEST(MrclamConverter, PerSourceClutterLabelsNameEachRobotConsistentlyAndLeaveLandmarkLabelsAlone) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  ConvertOptions options;
  options.classes = 3;
  options.misclassification = 0.0;  // exact labels: every sighting of robot s is labelled s mod 3
  const MeasurementLog uniform = convertMrclam(folder.string(), options);
  options.clutterLabels = ClutterLabels::PerSource;
  const MeasurementLog perSource = convertMrclam(folder.string(), options);
  std::map<int, std::set<int>> labelsOfRobot;
  std::size_t sightings = 0;
  for (std::size_t k = 0; k < perSource.steps.size(); ++k) {
    for (std::size_t i = 0; i < perSource.steps[k].detections.size(); ++i) {
      const Detection& d = perSource.steps[k].detections[i];
      if (d.clutterSource) {
        ++sightings;
        EXPECT_GE(*d.clutterSource, 1);
        EXPECT_LE(*d.clutterSource, 5);
        labelsOfRobot[*d.clutterSource].insert(*d.label);
      } else {
        EXPECT_EQ(d.label, uniform.steps[k].detections[i].label);  // same draws for everything else
      }
    }
  }
  EXPECT_EQ(sightings, 407u);  // robot 1 of Dataset 6: 407 sightings of other robots (SOURCE.txt)
  for (const auto& [robot, labels] : labelsOfRobot) {
    EXPECT_EQ(labels, std::set<int>{robot % 3}) << "robot " << robot;
  }
  TempDir dir;
  MeasurementLog back;
  test::writeAndReadBack(perSource, dir, "per-source.jsonl", &back);
  std::size_t sourcesBack = 0;
  for (const TimeStep& step : back.steps) {
    for (const Detection& d : step.detections) sourcesBack += d.clutterSource ? 1 : 0;
  }
  EXPECT_EQ(sourcesBack, 407u);
}

TEST(MrclamConverter, StepsSplitTheOdometryAtMeasurementStamps) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  const MeasurementLog log = convertMrclam(folder.string(), ConvertOptions{});
  const auto odometry = rawRows((folder / "Robot1_Odometry.dat").string());
  const auto measurements = rawRows((folder / "Robot1_Measurement.dat").string());
  // Every detection sits at the step of its own stamp, in file order.
  std::size_t i = 0;
  for (const TimeStep& step : log.steps) {
    for (const Detection& detection : step.detections) {
      ASSERT_LT(i, measurements.size());
      EXPECT_EQ(step.time, measurements[i][0]);
      EXPECT_EQ(detection.geometry(0), measurements[i][2]);
      EXPECT_EQ(detection.geometry(1), measurements[i][3]);
      ++i;
    }
  }
  EXPECT_EQ(i, measurements.size());
  std::size_t checked = 0;
  // Across a split, the two parts compose to the unsplit unicycle arc of the command in force.
  for (std::size_t k = 1; k + 1 < log.steps.size(); ++k) {
    if (log.steps[k].detections.empty()) continue;
    const double t = log.steps[k].time;
    const auto after = std::upper_bound(odometry.begin(), odometry.end(), t,
                                        [](double time, const std::vector<double>& row) { return time < row[0]; });
    if (after == odometry.begin() || after == odometry.end()) continue;
    const auto& command = *(after - 1);
    if (command[0] == t || log.steps[k + 1].time != (*after)[0] || log.steps[k - 1].time != command[0]) continue;
    const Odometry whole = composeOdometry(*log.steps[k].odometry, *log.steps[k + 1].odometry);
    const double dt = (*after)[0] - command[0];
    const SE2 arc = SE2::Exp(Vector3(command[1] * dt, 0.0, command[2] * dt));
    EXPECT_TRUE(std::get<SE2>(whole.increment).equals(arc, 1e-12)) << "step " << k;
    // The white-noise model: splitting an interval leaves its covariance as it was (to first order).
    const Vector3 slip(1e-6, kMrclamLateralIntensity, 1e-6);
    const Odometry unsplit = UnicycleModel(kMrclamVelocityIntensity / dt, kMrclamTurnRateIntensity / dt, slip)
                                 .integrate(command[1], command[2], dt);
    EXPECT_LT((whole.covariance - unsplit.covariance).cwiseAbs().maxCoeff(),
              1e-2 * unsplit.covariance.cwiseAbs().maxCoeff())
        << whole.covariance << "\n"
        << unsplit.covariance;
    if (++checked == 20) break;
  }
  EXPECT_EQ(checked, 20u);
}

TEST(MrclamConverter, SameSeedSameBytesAndResidualsReported) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  ConvertOptions options;
  options.robot = 3;
  options.classes = 3;
  options.misclassification = 0.1;
  options.seed = 21;
  options.keyframePeriod = 1.0;
  TempDir dir;
  ConversionStats stats;
  const MeasurementLog log = convertMrclam(folder.string(), options, &stats);
  const std::string a = test::writeAndReadBack(log, dir, "a.jsonl");
  const std::string b = test::writeAndReadBack(convertMrclam(folder.string(), options), dir, "b.jsonl");
  EXPECT_TRUE(a == b);
  const RawCounts raw = countRaw(folder, 3);
  EXPECT_EQ(stats.detections + stats.detectionsDroppedByKeyframing, raw.measurements);
  EXPECT_EQ(stats.datasetDetections, raw.measurements);
  // Clutter labels are uniform; landmark labels follow the categorical model.
  options.seed = 22;
  EXPECT_GT(test::expectSameExceptLabels(log, convertMrclam(folder.string(), options)), 0u);

  const LogResidualStatistics residuals = computeResidualStatistics(log);
  EXPECT_GT(residuals.detectionsEvaluated, 0u);
  EXPECT_EQ(residuals.detectionsClutter, stats.clutter);
  ASSERT_EQ(residuals.detection.size(), 2u);
  // The stated sigmas hold about 95 % of this robot's residuals within 1.96σ, as their Gaussian would (calibrated
  // on the five robots pooled; the MAD-based sigmas 0.13 m and 0.01 rad held 89 % of the ranges here).
  EXPECT_NEAR(residuals.detection[0].within95, 0.95, 0.04);
  EXPECT_NEAR(residuals.detection[1].within95, 0.95, 0.07);
  std::printf("%s", formatResidualStatistics(residuals).c_str());
}

TEST(MrclamConverter, RejectsAnUnknownRobot) {
  SEMSLAM_REQUIRE_DATA(folder, kFolder);
  ConvertOptions options;
  options.robot = 6;
  EXPECT_THROW(convertMrclam(folder.string(), options), InputError);
}

// Numbers a log may not hold are refused at the dataset row that made them (they were reported as "step 2" of the
// log, or at the folder: issue 16).
namespace {

/// A dataset folder of robot 1 with three commands (stamps 100, 100.5, 101), two measurements (100.5, 100.75) and
/// three Vicon samples; `edits` replaces whole files.
void writeSmallFolder(TempDir& dir, const std::map<std::string, std::string>& edits = {}) {
  std::map<std::string, std::string> files = {
      {"Barcodes.dat", "# subject barcode\n1 5\n6 27\n7 36\n"},
      {"Landmark_Groundtruth.dat", "# subject x y x_sd y_sd\n6 1.0 2.0 0.0001 0.0001\n7 3.0 -1.0 0.0001 0.0001\n"},
      {"Robot1_Odometry.dat", "# t v omega\n100.00 0.1 0.0\n100.50 0.1 0.1\n101.00 0.1 0.1\n"},
      {"Robot1_Measurement.dat", "# t barcode range bearing\n100.50 27 2.2 1.1\n100.75 36 3.1 -0.3\n"},
      {"Robot1_Groundtruth.dat", "# t x y theta\n100.00 0 0 0\n100.50 0.05 0 0.05\n101.00 0.1 0 0.1\n"}};
  for (const auto& [name, text] : edits) files[name] = text;
  for (const auto& [name, text] : files) dir.write(name, text);
}

}  // namespace

TEST(MrclamConverter, NumbersALogMayNotHoldAreRefusedAtTheirRow) {
  TempDir dir;
  const std::string folder = dir.path("");
  const auto writeFolder = [&](const std::map<std::string, std::string>& edits) { writeSmallFolder(dir, edits); };
  writeFolder({});
  EXPECT_EQ(convertMrclam(folder, ConvertOptions{}).steps.size(), 4u);  // stamps 100, 100.5, 100.75, 101

  writeFolder({{"Robot1_Measurement.dat", "# t barcode range bearing\n100.50 27 2.2 1.1\n100.75 36 1e-300 -0.3\n"}});
  EXPECT_INPUT_ERROR(convertMrclam(folder, ConvertOptions{}), dir.path("Robot1_Measurement.dat"), 3,
                     "the range must be at least");
  writeFolder({{"Landmark_Groundtruth.dat", "# subject x y x_sd y_sd\n6 1.0 2.0 0.0001 0.0001\n7 2e7 -1.0 0.0001 0.0001\n"}});
  EXPECT_INPUT_ERROR(convertMrclam(folder, ConvertOptions{}), dir.path("Landmark_Groundtruth.dat"), 3,
                     "landmark_truth[1].position[0]");
  // The command of line 3 (t = 100.5) drives the step at 100.75.
  writeFolder({{"Robot1_Odometry.dat", "# t v omega\n100.00 0.1 0.0\n100.50 1e300 0.1\n101.00 0.1 0.1\n"}});
  EXPECT_INPUT_ERROR(convertMrclam(folder, ConvertOptions{}), dir.path("Robot1_Odometry.dat"), 3,
                     "odometry.increment[0]");
  // The step at 100.75 is interpolated towards the sample of line 4.
  writeFolder({{"Robot1_Groundtruth.dat", "# t x y theta\n100.00 0 0 0\n100.50 0.05 0 0.05\n101.00 2.1e7 0 0.1\n"}});
  EXPECT_INPUT_ERROR(convertMrclam(folder, ConvertOptions{}), dir.path("Robot1_Groundtruth.dat"), 4, "true_pose[0]");
}

// --command-delay: a command takes effect that long after its stamp, so its step starts there and the motion before
// it is the previous command's (docs/datasets.md, "The command delay").
TEST(MrclamConverter, ACommandDelayShiftsWhereEachCommandTakesEffect) {
  TempDir dir;
  writeSmallFolder(dir, {{"Robot1_Odometry.dat", "# t v omega\n100.00 0.1 0.0\n100.50 0.2 0.4\n101.00 0.1 0.1\n"}});
  const std::string folder = dir.path("");
  ConvertOptions options;
  options.commandDelay = 0.2;
  const MeasurementLog log = convertMrclam(folder, options);
  // Steps at the delayed command stamps 100.2, 100.7, 101.2 and the measurement stamps 100.5, 100.75.
  std::vector<double> times;
  for (const TimeStep& step : log.steps) times.push_back(step.time);
  const std::vector<double> expected = {100.2, 100.5, 100.7, 100.75, 101.2};
  ASSERT_EQ(times.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(times[k], expected[k], 1e-9) << "step " << k;
  const auto arc = [](double v, double omega, double dt) { return SE2::Exp(Vector3(v * dt, 0.0, omega * dt)); };
  const auto increment = [&](std::size_t k) { return std::get<SE2>(log.steps[k].odometry->increment); };
  // 100.5 → 100.7: still the first command (the second, stamped 100.5, takes effect at 100.7).
  EXPECT_TRUE(increment(2).equals(arc(0.1, 0.0, 0.2), 1e-12));
  // 100.7 → 100.75 and 100.75 → 101.2: the second command.
  EXPECT_TRUE(increment(3).equals(arc(0.2, 0.4, 0.05), 1e-12));
  EXPECT_TRUE(increment(4).equals(arc(0.2, 0.4, 0.45), 1e-12));
  // Without the delay the second command drives the step at 100.75 from 100.5 on.
  const MeasurementLog undelayed = convertMrclam(folder, ConvertOptions{});
  EXPECT_TRUE(std::get<SE2>(undelayed.steps[2].odometry->increment).equals(arc(0.2, 0.4, 0.25), 1e-12));

  for (double refused : {-0.1, kMrclamMaxCommandDelay + 0.1, std::nan("")}) {
    options.commandDelay = refused;
    EXPECT_THROW(convertMrclam(folder, options), InputError) << refused;
  }
}
