// `semslam optimize`: reports, marginals, formats, and exit code 2 with a clear message on malformed input.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/RunCommand.h"
#include "support/TestData.h"
#include "semslam/core/Version.h"

using semslam::test::runSemslam;

namespace {

class TempDir {
 public:
  TempDir() : path_(std::filesystem::temp_directory_path() / ("semslam_cli_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name, const std::string& contents) const {
    const auto path = path_ / name;
    std::ofstream(path) << contents;
    return path.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

const char* const kGoodGraph =
    "VERTEX_SE2 0 0 0 0\n"
    "VERTEX_SE2 1 1 0 0\n"
    "VERTEX_SE2 2 2 0.1 0\n"
    "EDGE_SE2 0 1 1 0 0 100 0 0 100 0 400\n"
    "EDGE_SE2 1 2 1 0 0 100 0 0 100 0 400\n"
    "EDGE_SE2 0 2 2.1 0 0 100 0 0 100 0 400\n";

}  // namespace

TEST(OptimizeCommand, WritesReportMarginalsAndGraph) {
  TempDir dir;
  const std::string input = dir.file("small.g2o", kGoodGraph);
  const auto run = runSemslam("optimize " + input + " --solver lm --marginals 2,1 --report " +
                              dir.path("report.json") + " --out " + dir.path("out.g2o"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json report = readJson(dir.path("report.json"));
  for (const char* field : {"initial_chi2", "final_chi2", "iterations", "time_s", "marginals", "joint_marginal"}) {
    EXPECT_TRUE(report.contains(field)) << field;
  }
  EXPECT_LT(report["final_chi2"].get<double>(), report["initial_chi2"].get<double>());
  EXPECT_EQ(report["version"], std::string(semslam::version()));
  EXPECT_EQ(report["joint_marginal"]["keys"], nlohmann::json::array({"2", "1"}));
  EXPECT_EQ(report["joint_marginal"]["matrix"].size(), 6u);
  EXPECT_EQ(report["marginals"]["2"].size(), 3u);
  // The joint matrix's diagonal blocks are the per-key marginals.
  EXPECT_DOUBLE_EQ(report["joint_marginal"]["matrix"][3][3].get<double>(),
                   report["marginals"]["1"][0][0].get<double>());
  EXPECT_TRUE(std::filesystem::exists(dir.path("out.g2o")));
  // The written graph is at the optimum: re-optimising it changes nothing.
  const auto again = runSemslam("optimize " + dir.path("out.g2o") + " --report " + dir.path("again.json"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NEAR(readJson(dir.path("again.json"))["initial_chi2"].get<double>(), report["final_chi2"].get<double>(),
              1e-9);
}

TEST(OptimizeCommand, IsamFileWithTypedIds) {
  SEMSLAM_REQUIRE_DATA(path, "isam/cityTrees10000.txt");
  TempDir dir;
  const auto run = runSemslam("optimize " + path.string() + " --format isam --marginals x12,l3 --report " +
                              dir.path("report.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json report = readJson(dir.path("report.json"));
  EXPECT_EQ(report["joint_marginal"]["keys"], nlohmann::json::array({"x12", "l3"}));
  EXPECT_EQ(report["joint_marginal"]["matrix"].size(), 5u);
  EXPECT_TRUE(report["converged"].get<bool>());
}

TEST(OptimizeCommand, MalformedInputExitsWithCodeTwoNamingFileAndLine) {
  TempDir dir;
  struct Case {
    const char* name;
    std::string contents;
    const char* expected;  // a fragment of the message
  };
  const std::vector<Case> cases = {
      {"truncated.g2o", "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0\n", ":2:"},
      {"nonnumeric.g2o", "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 abc 0\n", ":2:"},
      {"unknown_vertex.g2o", "VERTEX_SE2 0 0 0 0\nEDGE_SE2 0 7 1 0 0 1 0 0 1 0 1\n", ":2:"},
      {"not_pd.g2o", "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 -1 0 1\n", ":3:"},
  };
  for (const Case& c : cases) {
    const std::string input = dir.file(c.name, c.contents);
    const auto run = runSemslam("optimize " + input);
    EXPECT_EQ(run.exitCode, 2) << c.name << ": " << run.output;
    EXPECT_NE(run.output.find(c.name), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << run.output;
  }
  const auto missing = runSemslam("optimize " + dir.path("does_not_exist.g2o"));
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  const auto badKey = runSemslam("optimize " + dir.file("good.g2o", kGoodGraph) + " --marginals 9");
  EXPECT_EQ(badKey.exitCode, 2) << badKey.output;
  const auto badSolver = runSemslam("optimize " + dir.file("good2.g2o", kGoodGraph) + " --solver newton");
  EXPECT_EQ(badSolver.exitCode, 2) << badSolver.output;
}

TEST(OptimizeCommand, ReportIsNotLeftHalfWrittenOnFailure) {
  TempDir dir;
  const std::string input = dir.file("bad.g2o", "VERTEX_SE2 0 0 0 0\nEDGE_SE2 0 1\n");
  const auto run = runSemslam("optimize " + input + " --report " + dir.path("report.json"));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path("report.json")));
}

TEST(OptimizeCommand, IncrementalReplayReachesTheBatchOptimumAndReportsStepTimes) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/intel/originalDataset/intel.g2o");
  TempDir dir;
  const auto batch = runSemslam("optimize " + path.string() + " --report " + dir.path("batch.json"));
  ASSERT_EQ(batch.exitCode, 0) << batch.output;
  const auto run = runSemslam("optimize " + path.string() + " --incremental --marginals 942,941 --report " +
                              dir.path("inc.json") + " --step-times " + dir.path("steps.csv"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json report = readJson(dir.path("inc.json"));
  for (const char* field : {"final_chi2", "time_s", "replay_time_s", "worst_step_time_s", "steps",
                            "final_convergence_time_s", "joint_marginal"}) {
    EXPECT_TRUE(report.contains(field)) << field;
  }
  const double optimum = readJson(dir.path("batch.json"))["final_chi2"].get<double>();
  EXPECT_NEAR(report["final_chi2"].get<double>(), optimum, 1e-4 * optimum);
  EXPECT_EQ(report["steps"].get<int>(), 943);
  EXPECT_LE(report["worst_step_time_s"].get<double>(), report["replay_time_s"].get<double>());
  std::ifstream steps(dir.path("steps.csv"));
  std::string line;
  int lines = 0;
  while (std::getline(steps, line)) ++lines;
  EXPECT_EQ(lines, 944);  // header + one per step

  // Without the final convergence the estimate is the online one: near, not at, the optimum.
  const auto online = runSemslam("optimize " + path.string() + " --incremental --no-final-convergence --report " +
                                 dir.path("online.json"));
  ASSERT_EQ(online.exitCode, 0) << online.output;
  const double onlineChi2 = readJson(dir.path("online.json"))["final_chi2"].get<double>();
  EXPECT_GE(onlineChi2, optimum * (1.0 - 1e-9));
  EXPECT_LE(onlineChi2, optimum * 1.01);
}

TEST(OptimizeCommand, AGraphThatLeavesVerticesFreeSaysWhichAndHowToHoldThem) {
  TempDir dir;
  struct Case {
    const char* name;
    std::string contents;
    const char* expected;  // names the free vertices
  };
  // (A vertex that no edge names is simply left where it is: it is not part of the system.)
  const std::vector<Case> cases = {
      // Two separate parts: the first vertex holds 0-1, nothing holds 2-3.
      {"two_parts.g2o",
       "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nVERTEX_SE2 2 5 0 0\nVERTEX_SE2 3 6.5 0 0\n"
       "EDGE_SE2 0 1 1 0 0 100 0 0 100 0 400\nEDGE_SE2 2 3 1 0 0 100 0 0 100 0 400\n",
       "the 2 variables 2, 3"},
      // The triangle of kGoodGraph, held by vertex 0, and a separate pair with no anchor.
      {"triangle_and_pair.g2o",
       std::string(kGoodGraph) + "VERTEX_SE2 7 9 0 0\nVERTEX_SE2 8 10.5 0 0\nEDGE_SE2 7 8 1 0 0 100 0 0 100 0 400\n",
       "the 2 variables 7, 8"},
  };
  for (const Case& c : cases) {
    const std::string input = dir.file(c.name, c.contents);
    for (const char* mode : {" --solver gn", " --incremental"}) {
      const auto run = runSemslam("optimize " + input + mode);
      EXPECT_EQ(run.exitCode, 2) << c.name << mode << ": " << run.output;
      EXPECT_NE(run.output.find(c.name), std::string::npos) << run.output;
      EXPECT_NE(run.output.find(c.expected), std::string::npos) << run.output;
      EXPECT_NE(run.output.find("FIX line"), std::string::npos) << run.output;
      EXPECT_EQ(run.output.find("CHOLMOD"), std::string::npos) << run.output;
    }
  }
}

TEST(OptimizeCommand, TheIncrementalReplayShowsProgressUnlessQuiet) {
  TempDir dir;
  const std::string input = dir.file("progress.g2o", kGoodGraph);
  const auto shown = runSemslam("optimize " + input + " --incremental");
  ASSERT_EQ(shown.exitCode, 0) << shown.output;
  EXPECT_NE(shown.output.find("optimize --incremental: 3/3"), std::string::npos) << shown.output;
  const auto quiet = runSemslam("optimize " + input + " --incremental --quiet");
  ASSERT_EQ(quiet.exitCode, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("optimize --incremental:"), std::string::npos) << quiet.output;
}
