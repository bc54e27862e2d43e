// semslam demo: paper B's mm-nh and known on the built-in ambiguous log (run/Demo.h), end to end: the summary
// names both methods, and the folder holds the log and both run folders that python/plot_run.py draws.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/RunCommand.h"

namespace fs = std::filesystem;

TEST(DemoCommand, RunsMaxMixturesAndKnownOnTheBuiltInLog) {
  const fs::path dir = fs::temp_directory_path() / "semslam_demo_command";
  fs::remove_all(dir);
  const auto result = semslam::test::runSemslam("demo --out \"" + dir.string() + "\"");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("mm-nh: ATE"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("known: ATE"), std::string::npos) << result.output;
  for (const char* file : {"demo_log.jsonl", "metrics.json", "trajectory.tum", "truth.tum", "landmarks.csv",
                           "landmarks_truth.csv", "covariances.csv", "associations.csv", "known/metrics.json"}) {
    EXPECT_TRUE(fs::exists(dir / file)) << file;
  }
  std::ifstream metricsFile(dir / "metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(metricsFile);
  EXPECT_EQ(metrics["method"], "mm-nh");
  EXPECT_LT(metrics["ate_rmse"].get<double>(), 2.0);
  fs::remove_all(dir);
}
