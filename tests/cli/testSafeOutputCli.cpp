// Safe output from the command line: an interrupted command leaves the previous complete output or nothing and
// says what was not written (through the deterministic test hook SEMSLAM_TEST_INTERRUPT_AFTER_FILES,
// io/InterruptCleanup.h); an existing non-empty --out folder needs --overwrite, which replaces it whole; a link
// or device at the destination and an output equal to an input are refused (issue 16).

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/IoTesting.h"
#include "support/RunCommand.h"

using semslam::test::CommandResult;
using semslam::test::runSemslam;

namespace {

namespace fs = std::filesystem;


/// Runs the command with the interruption hook set to `setting` ("3", "3:TERM").
CommandResult interruptedAfter(const std::string& setting, const std::string& arguments) {
  ::setenv("SEMSLAM_TEST_INTERRUPT_AFTER_FILES", setting.c_str(), 1);
  CommandResult result = runSemslam(arguments);
  ::unsetenv("SEMSLAM_TEST_INTERRUPT_AFTER_FILES");
  return result;
}

std::size_t files(const std::string& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), {}));
}

TEST(SafeOutputCli, AnInterruptedSimulationLeavesNoFolderThatLooksFinished) {
  // SIGINT during `simulate aliased2d --tracks 3000` left 382 complete tracks and a .tmp.
  const semslam::test::TempDir scratch;
  const std::string out = scratch.path("tracks");
  const CommandResult result =
      interruptedAfter("3", "simulate aliased2d --tracks 10 --steps 5 --quiet --out " + out);
  EXPECT_EQ(result.exitCode, 130) << result.output;
  EXPECT_NE(result.output.find("interrupted by SIGINT"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("not written: " + out), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(files(scratch.path("")), 0u);  // no staging folder, no temporary file
}

TEST(SafeOutputCli, AnInterruptedRerunLeavesThePreviousCompleteOutput) {
  const semslam::test::TempDir scratch;
  const std::string out = scratch.path("tracks");
  ASSERT_EQ(runSemslam("simulate aliased2d --tracks 10 --steps 5 --quiet --out " + out).exitCode, 0);
  ASSERT_EQ(files(out), 10u);
  const CommandResult result =
      interruptedAfter("2:TERM", "simulate aliased2d --tracks 3 --steps 5 --quiet --overwrite --out " + out);
  EXPECT_EQ(result.exitCode, 143) << result.output;
  EXPECT_NE(result.output.find("interrupted by SIGTERM"), std::string::npos) << result.output;
  EXPECT_EQ(files(out), 10u);
  EXPECT_EQ(files(scratch.path("")), 1u);
}

TEST(SafeOutputCli, AnInterruptedRunLeavesNoRunFolder) {
  // SIGINT while a run folder was written left a 0-byte trajectory.tum, stray .tmp files, no metrics.json.
  const semslam::test::TempDir scratch;
  const std::string log = scratch.path("run.jsonl");
  ASSERT_EQ(runSemslam("simulate semantic --steps 20 --seed 3 --out " + log).exitCode, 0);
  const std::string out = scratch.path("run");
  const CommandResult result = interruptedAfter("2", "run --method known --quiet --in " + log + " --out " + out);
  EXPECT_EQ(result.exitCode, 130) << result.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(files(scratch.path("")), 1u);  // the log alone
}

TEST(SafeOutputCli, ANonEmptyOutFolderNeedsOverwriteWhichReplacesItWhole) {
  const semslam::test::TempDir scratch;
  const std::string log = scratch.path("run.jsonl");
  ASSERT_EQ(runSemslam("simulate semantic --steps 20 --seed 3 --out " + log).exitCode, 0);
  const std::string out = scratch.path("run");
  fs::create_directories(out);
  std::ofstream(out + "/hypotheses.jsonl") << "stale\n";
  const CommandResult refused = runSemslam("run --method known --quiet --in " + log + " --out " + out);
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_NE(refused.output.find("--overwrite"), std::string::npos) << refused.output;
  ASSERT_EQ(runSemslam("run --method known --quiet --overwrite --in " + log + " --out " + out).exitCode, 0);
  EXPECT_FALSE(fs::exists(out + "/hypotheses.jsonl"));
  EXPECT_TRUE(fs::exists(out + "/metrics.json"));
  EXPECT_EQ(runSemslam("run --method known --quiet --overwrite --in " + log + " --out " + scratch.path("")).exitCode,
            2);  // a folder holding the input
  EXPECT_TRUE(fs::exists(log));
}

TEST(SafeOutputCli, LinksDevicesAndInputsAreNeverOverwritten) {
  const semslam::test::TempDir scratch;
  const std::string graph = scratch.path("g.g2o");
  std::ofstream(graph) << "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n";
  const std::string victim = scratch.path("victim.txt");
  std::ofstream(victim) << "precious";
  const std::string link = scratch.path("out.g2o");
  fs::create_symlink(victim, link);
  EXPECT_EQ(runSemslam("optimize " + graph + " --out " + link).exitCode, 2);
  std::ifstream in(victim);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "precious");
  EXPECT_EQ(runSemslam("optimize " + graph + " --out /dev/full").exitCode, 2);
  struct stat status {};
  ASSERT_EQ(::lstat("/dev/full", &status), 0);
  EXPECT_TRUE(S_ISCHR(status.st_mode));
  const CommandResult same = runSemslam("optimize " + graph + " --report " + graph);
  EXPECT_EQ(same.exitCode, 2) << same.output;
  EXPECT_NE(same.output.find("is also an input"), std::string::npos) << same.output;
}

}  // namespace
