// RobustnessStudy: a tiny study on a simulated log (2 levels per axis, 2 seeds): the rows are complete and in
// order, seeds are paired (the overlapping cell of both sweeps, and a method's result does not depend on which
// other methods run), the CSVs are identical with 1 and 2 threads (times only in timings.csv), stuck is defined for mm / mm-nh only; the t
// interval; and the CLI: a small run writes its files (study.json with the shared method options), bad input
// exits 2.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "semslam/core/Version.h"
#include "semslam/study/RobustnessStudy.h"
#include "study/StudyTesting.h"
#include "support/RunCommand.h"

namespace semslam {
namespace {

const MeasurementLog& tinyLog() {
  static const MeasurementLog log = test::smallSemanticLog(40);
  return log;
}

RobustnessStudyOptions tinyOptions() {
  RobustnessStudyOptions options;
  options.noiseScales = {0, 2};
  options.misclassificationRates = {0, 0.1};  // 0: the model floor keeps the pipeline alive
  options.seeds = 2;
  options.threads = 2;
  return options;
}

// One test for the whole tiny study (ctest runs every test in its own process: a fixture would redo the study).
TEST(RobustnessStudy, TinyStudy) {
  RobustnessStudyOptions options = tinyOptions();
  const RobustnessStudy twoThreads = runRobustnessStudy(tinyLog(), options);
  options.threads = 1;
  const RobustnessStudy oneThread = runRobustnessStudy(tinyLog(), options);

  // Rows are complete and in order.
  const std::vector<RobustnessRow>& rows = twoThreads.rows;
  ASSERT_EQ(rows.size(), 2u * 2u * 2u * 5u);  // axes x levels x seeds x methods
  const std::vector<AssociationStrategy> methods = allStrategies();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RobustnessRow& row = rows[i];
    const std::size_t cell = i / 5;
    EXPECT_EQ(row.method, strategyName(methods[i % 5]));
    EXPECT_EQ(row.axis, cell < 4 ? RobustnessAxis::OdometryNoise : RobustnessAxis::Misclassification);
    EXPECT_EQ(row.seed, static_cast<int>(cell % 2));
    EXPECT_TRUE(row.error.empty()) << row.error;
    EXPECT_TRUE(std::isfinite(row.ateRmse)) << row.method;
    EXPECT_TRUE(std::isfinite(row.daAccuracy)) << row.method;
    // Over true landmarks only: the log's clutter leaves it, so it differs from daAccuracy but is a fraction too.
    EXPECT_GE(row.daAccuracyReal, 0.0) << row.method;
    EXPECT_LE(row.daAccuracyReal, 1.0) << row.method;
    EXPECT_TRUE(row.landmarksTrue.has_value());
    const bool maxMixture = row.method == "mm" || row.method == "mm-nh";
    EXPECT_EQ(row.stuck.has_value(), maxMixture) << row.method;
    if (row.method == "known") EXPECT_EQ(row.daAccuracy, 1.0);
    if (row.method == "known") EXPECT_EQ(row.daAccuracyReal, 1.0);
  }
  EXPECT_EQ(rows[0].level, 0.0);
  EXPECT_EQ(rows[10].level, 2.0);
  EXPECT_EQ(rows[20].level, 0.0);
  EXPECT_EQ(rows[30].level, 0.1);

  // The same CSV with one and two threads (the wall-clock times are in timings.csv only).
  EXPECT_EQ(robustnessCsv(oneThread.rows), robustnessCsv(twoThreads.rows));
  EXPECT_EQ(robustnessSummaryCsv(oneThread.rows), robustnessSummaryCsv(twoThreads.rows));
  const std::string timings = robustnessTimingsCsv(rows, twoThreads.layout, 5);
  EXPECT_EQ(timings.rfind("axis,level,seed,method,rank,time_s,threads,ranks,wall_time_s\n", 0), 0u);
  EXPECT_EQ(std::count(timings.begin(), timings.end(), '\n'), 1 + 40);

  // Summary: one row per (axis, level, method).
  const std::string summary = robustnessSummaryCsv(rows);
  EXPECT_EQ(std::count(summary.begin(), summary.end(), '\n'), 1 + 2 * 2 * 5);
  EXPECT_EQ(summary.rfind("axis,level,method,n,ate_mean", 0), 0u);

  // Paired seeds. A second study whose two sweeps meet at (s = 1, p = 0.1), with known and ml only: the two
  // sweeps' copies of the shared cell are equal, and known's results equal the full study's on the same cells
  // (every method sees the cell's one log, whoever else runs on it).
  options = tinyOptions();
  options.noiseScales = {1};
  options.misclassificationRates = {0.1};
  options.methods = {AssociationStrategy::Known, AssociationStrategy::MaximumLikelihood};
  const RobustnessStudy pair = runRobustnessStudy(tinyLog(), options);
  ASSERT_EQ(pair.rows.size(), 2u * 2u * 2u);
  for (int seed = 0; seed < 2; ++seed) {
    for (int m = 0; m < 2; ++m) {
      const RobustnessRow& noise = pair.rows[seed * 2 + m];
      const RobustnessRow& rate = pair.rows[4 + seed * 2 + m];
      EXPECT_EQ(noise.ateRmse, rate.ateRmse);
      EXPECT_EQ(noise.daAccuracy, rate.daAccuracy);
      EXPECT_EQ(noise.landmarksEstimated, rate.landmarksEstimated);
    }
    const RobustnessRow& full = rows[30 + seed * 5];  // misclassification 0.1 (at s = 1), seed, known
    ASSERT_EQ(full.method, "known");
    EXPECT_EQ(full.level, 0.1);
    EXPECT_EQ(pair.rows[4 + seed * 2].ateRmse, full.ateRmse);
    EXPECT_EQ(pair.rows[4 + seed * 2].rotRmse, full.rotRmse);
  }
}

TEST(RobustnessStudy, StudentIntervalMatchesReference) {
  EXPECT_NEAR(studentT975(1), 12.706204736, 1e-8);
  EXPECT_NEAR(studentT975(9), 2.262157163, 1e-8);
  EXPECT_NEAR(studentT975(40), 2.021075383, 1e-6);   // Cornish–Fisher
  EXPECT_NEAR(studentT975(100), 1.983971518, 1e-6);
  const MeanInterval interval = meanInterval({1.0, 2.0, 3.0, 4.0, std::nan("")});
  EXPECT_EQ(interval.n, 4);
  EXPECT_DOUBLE_EQ(interval.mean, 2.5);
  const double half = 3.182446305284263 * std::sqrt(5.0 / 3.0) / 2.0;
  EXPECT_NEAR(interval.low, 2.5 - half, 1e-12);
  EXPECT_NEAR(interval.high, 2.5 + half, 1e-12);
  EXPECT_TRUE(std::isnan(meanInterval({1.0}).low));
}

TEST(RobustnessStudy, InvalidOptionsThrow) {
  RobustnessStudyOptions options = tinyOptions();
  options.noiseScales = {};
  EXPECT_THROW(validateRobustnessOptions(options), std::invalid_argument);
  options = tinyOptions();
  options.noiseScales = {-1};
  EXPECT_THROW(validateRobustnessOptions(options), std::invalid_argument);
  options = tinyOptions();
  options.misclassificationRates = {1.0};
  EXPECT_THROW(validateRobustnessOptions(options), std::invalid_argument);
  options = tinyOptions();
  options.methods = {};
  EXPECT_THROW(validateRobustnessOptions(options), std::invalid_argument);
}

TEST(StudyCommand, SmallRunWritesItsFilesAndBadInputExitsTwo) {
  test::StudyScratch scratch;
  const std::string log = scratch.file("log.jsonl");
  writeMeasurementLog(log, test::smallSemanticLog(20));
  const std::string out = scratch.file("out");
  const std::string base = "study robustness --log \"" + log + "\" --out \"" + out + "\" --seeds 1 --quiet ";
  const test::CommandResult ok =
      test::runSemslam(base + "--methods known,mm --odom-noise-scale 0,1 --misclassification 0.2 --null-weight 0.2");
  ASSERT_EQ(ok.exitCode, 0) << ok.output;
  const std::string csv = test::fileBytes(out + "/robustness.csv");
  EXPECT_EQ(csv.rfind("axis,level,seed,method,ate_rmse,rot_rmse,da_accuracy,da_accuracy_real,landmarks_estimated,"
                      "landmarks_true,stuck\n",
                      0),
            0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3 * 2);
  EXPECT_FALSE(test::fileBytes(out + "/robustness_summary.csv").empty());
  const std::string timings = test::fileBytes(out + "/timings.csv");
  EXPECT_EQ(timings.rfind("axis,level,seed,method,rank,time_s,threads,ranks,wall_time_s\n", 0), 0u) << timings;
  EXPECT_EQ(std::count(timings.begin(), timings.end(), '\n'), 1 + 3 * 2);
  const nlohmann::json settings = nlohmann::json::parse(test::fileBytes(out + "/study.json"));
  EXPECT_EQ(settings["schema"], "semslam.study.robustness/3");
  EXPECT_EQ(settings["version"], std::string(semslam::version()));
  EXPECT_EQ(settings["methods"], "known,mm");
  EXPECT_EQ(settings["runs"], 6);
  // Each method's settings as its runs were made (run/MethodSettings.h): the shared option block (MethodOptions.h)
  // with each default resolved for the method.
  const nlohmann::json& methods = settings.at("method_settings");
  ASSERT_EQ(methods.size(), 2u);
  for (const char* method : {"known", "mm"}) {
    EXPECT_EQ(methods.at(method).at("method"), method);
    EXPECT_DOUBLE_EQ(methods.at(method).at("association").at("null_weight").get<double>(), 0.2);
    EXPECT_TRUE(methods.at(method).at("association").at("unassigned_rate_weight").is_null());  // μ constant
    EXPECT_EQ(methods.at(method).at("pose_covariances"), false);
  }
  EXPECT_EQ(methods.at("known").at("association").at("loop_closure_branches"), 0);
  EXPECT_EQ(methods.at("mm").at("association").at("loop_closure_branches"), 16);
  EXPECT_TRUE(settings.contains("smoother"));
  for (const char* key : {"threads", "wall_time_s"}) EXPECT_FALSE(settings.contains(key)) << key;  // timings.csv

  for (const std::string bad : {"--methods known,magic", "--odom-noise-scale ,", "--odom-noise-scale=-1",
                                "--misclassification 1", "--misclassification 0.1,x", "--seeds 0"}) {
    const test::CommandResult result = test::runSemslam(base + bad);
    EXPECT_EQ(result.exitCode, 2) << bad << ": " << result.output;
  }
}

}  // namespace
}  // namespace semslam
