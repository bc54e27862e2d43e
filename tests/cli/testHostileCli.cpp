// Hostile command-line values and inputs: each is refused with exit code 2 and a short message, never converted
// silently, run unbounded, or echoed whole (issue 16).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/IoTesting.h"
#include "support/RunCommand.h"

using semslam::test::CommandResult;
using semslam::test::runSemslam;

namespace {

namespace fs = std::filesystem;


void expectRefused(const CommandResult& result, const std::string& fragment) {
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find(fragment), std::string::npos) << result.output;
}

const std::string kGraph = "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n";

TEST(HostileCli, ASeedPastTwoToTheSixtyFourIsRefusedNotSaturated) {
  const semslam::test::TempDir scratch;
  expectRefused(runSemslam("simulate semantic --seed 99999999999999999999999 --out " + scratch.path("a.jsonl")),
                "2^64 - 1");
  expectRefused(runSemslam("simulate aliased2d --seed -5 --out " + scratch.path("a.jsonl")), "non-negative");
  expectRefused(runSemslam("demo --seed 1e3 --out " + scratch.path("demo")), "non-negative");
  EXPECT_FALSE(fs::exists(scratch.path("a.jsonl")));
}

TEST(HostileCli, CountsOutOfTheirRangeAreRefused) {
  const semslam::test::TempDir scratch;
  const std::string graph = scratch.write("g.g2o", kGraph);
  expectRefused(runSemslam("optimize " + graph + " --max-iterations -5"), "--max-iterations");
  expectRefused(runSemslam("simulate semantic --landmarks 2000000000 --out " + scratch.path("a.jsonl")),
                "--landmarks");
  expectRefused(runSemslam("simulate semantic --steps 2000000000 --out " + scratch.path("a.jsonl")), "--steps");
  expectRefused(runSemslam("simulate semantic --classes 1000000 --out " + scratch.path("a.jsonl")), "--classes");
  expectRefused(runSemslam("simulate semantic --landmark-density 1e300 --out " + scratch.path("a.jsonl")),
                "landmarks");
  expectRefused(runSemslam("run --method hybrid --samples 100000000 --in " + graph + " --out " + scratch.path("r")),
                "--samples");
}

TEST(HostileCli, AHugeRpeDeltaIsRefusedQuickly) {
  // The delta was cast to size_t: 1e300 grew past 7.8 GB.
  const semslam::test::TempDir scratch;
  const std::string tum = scratch.write("t.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n");
  expectRefused(runSemslam("eval rpe --est " + tum + " --ref " + tum + " --delta 1e300"), "produced no pose pair");
}

TEST(HostileCli, ADeviceAsInputIsRefusedBeforeItIsRead) {
  expectRefused(runSemslam("optimize /dev/zero"), "not a regular file");
  expectRefused(runSemslam("check /dev/zero"), "not a regular file");
}

TEST(HostileCli, MessagesQuoteAShortEscapedExcerptOfTheValue) {
  // A 100,000-character value (about the most one argument can hold) and a terminal escape sequence.
  const CommandResult result = runSemslam("simulate semantic --seed $(printf '\\033[2J')" + std::string(100'000, '7') +
                                          " --out /nonexistent/a.jsonl");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_LT(result.output.size(), 2000u) << result.output.substr(0, 2000);
  EXPECT_EQ(result.output.find('\033'), std::string::npos);
}

TEST(HostileCli, NonFiniteResultsExitTwoNamingTheFileAndLine) {
  const semslam::test::TempDir scratch;
  const std::string isam = scratch.write("big.isam", "EDGE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE2 1 2 -1e308 0 0 1 0 0 1 0 1\n");
  const std::string out = scratch.path("out.g2o");
  expectRefused(runSemslam("optimize " + isam + " --format isam --out " + out), isam + ":2:");
  EXPECT_FALSE(fs::exists(out));
  const std::string ref = scratch.write("ref.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n");
  const std::string est = scratch.write("est.tum", "0 0 0 0 0 0 0 1\n1 1e308 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n");
  const CommandResult result = runSemslam("eval ate --json --est " + est + " --ref " + ref);
  expectRefused(result, est);
  EXPECT_EQ(result.output.find("null"), std::string::npos) << result.output;
}

}  // namespace
