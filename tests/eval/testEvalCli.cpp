// The `semslam eval` command: exit code 2 on malformed input, evo-like output, JSON with every statistic.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "semslam/core/Version.h"
#include "support/TempFile.h"
#include "support/TestData.h"

namespace semslam {
namespace {

struct CommandResult {
  int exitCode = -1;
  std::string out;
};

/// Runs the CLI with `arguments` (stderr discarded), returning its exit code and standard output.
CommandResult runCli(const std::string& arguments) {
  const std::string command = std::string("'") + SEMSLAM_CLI + "' " + arguments + " 2>/dev/null";
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

constexpr const char* kGood = "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 1 0 0 0 0 1\n3 3 1 1 0 0 0 1\n";

TEST(EvalCli, MalformedFileExitsWithCode2) {
  const test::TempFile good(kGood);
  const test::TempFile bad("0 0 0 0 0 0 0 1\n1 1 0 0 0 0 1\n");  // 7 numbers on line 2
  EXPECT_EQ(runCli("eval ate --est " + quoted(bad.path()) + " --ref " + quoted(good.path())).exitCode, 2);
  EXPECT_EQ(runCli("eval rpe --est " + quoted(good.path()) + " --ref " + quoted(bad.path())).exitCode, 2);
  const test::TempFile nan("0 0 0 0 0 0 0 1\n1 nan 0 0 0 0 0 1\n");
  EXPECT_EQ(runCli("eval ate --est " + quoted(nan.path()) + " --ref " + quoted(good.path())).exitCode, 2);
  EXPECT_EQ(runCli("eval ate --est /nonexistent/est.txt --ref " + quoted(good.path())).exitCode, 2);
  EXPECT_EQ(runCli("eval ate --est " + quoted(good.path()) + " --ref " + quoted(good.path()) + " --format kitti")
                .exitCode,
            2);  // 8 columns are no KITTI file
  EXPECT_EQ(runCli("eval ate --est " + quoted(good.path()) + " --ref " + quoted(good.path()) + " --align rigid")
                .exitCode,
            2);  // unknown choice: a usage error
  EXPECT_EQ(runCli("eval ate --ref " + quoted(good.path())).exitCode, 2);  // --est missing
}

TEST(EvalCli, PrintsStatisticsLikeEvoAndJson) {
  const test::TempFile ref(kGood);
  const test::TempFile est("0 0 0 0 0 0 0 1\n1 1 0.5 0 0 0 0 1\n2 2 1 0 0 0 0 1\n3 3 1 1 0 0 0 1\n");
  const CommandResult text = runCli("eval ate --est " + quoted(est.path()) + " --ref " + quoted(ref.path()));
  ASSERT_EQ(text.exitCode, 0);
  EXPECT_NE(text.out.find("APE w.r.t. translation part (m)\n(not aligned)\n\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("       max\t0.500000\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("      rmse\t0.250000\n"), std::string::npos) << text.out;

  const CommandResult json =
      runCli("eval ate --json --est " + quoted(est.path()) + " --ref " + quoted(ref.path()) + " --align sim3");
  ASSERT_EQ(json.exitCode, 0);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  for (const char* key : {"rmse", "mean", "median", "max", "min", "sse", "std", "pairs", "scale"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j.at("pairs").get<int>(), 4);
  EXPECT_EQ(j.at("version"), std::string(version()));

  const CommandResult rpe = runCli("eval rpe --json --est " + quoted(est.path()) + " --ref " + quoted(ref.path()) +
                                   " --delta 1 --delta-unit frames");
  ASSERT_EQ(rpe.exitCode, 0);
  const nlohmann::json r = nlohmann::json::parse(rpe.out);
  EXPECT_EQ(r.at("pairs").get<int>(), 3);
  EXPECT_FALSE(r.contains("scale"));
  EXPECT_NEAR(r.at("max").get<double>(), 0.5, 1e-12);
}

TEST(EvalCli, ReproducesEvoOnKitti) {
  SEMSLAM_REQUIRE_DATA(ref, "evo-testdata/KITTI_00_gt.txt");
  SEMSLAM_REQUIRE_DATA(est, "evo-testdata/KITTI_00_ORB.txt");
  const CommandResult ate = runCli("eval ate --json --format kitti --align se3 --est " + quoted(est.string()) +
                                   " --ref " + quoted(ref.string()));
  ASSERT_EQ(ate.exitCode, 0);
  EXPECT_NEAR(nlohmann::json::parse(ate.out).at("rmse").get<double>(), 1.3034497, 1e-6);
  const CommandResult rpe = runCli("eval rpe --json --format kitti --delta 10 --delta-unit m --est " +
                                   quoted(est.string()) + " --ref " + quoted(ref.string()));
  ASSERT_EQ(rpe.exitCode, 0);
  EXPECT_NEAR(nlohmann::json::parse(rpe.out).at("rmse").get<double>(), 0.2262613, 1e-6);
}

}  // namespace
}  // namespace semslam
