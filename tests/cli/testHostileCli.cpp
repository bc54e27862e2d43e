// Hostile command-line values and inputs: each is refused with exit code 2 and a short message, never converted
// silently, run unbounded, or echoed whole (issue 16).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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
  // A size_t option: CLI11 wrapped "-5" around to 2^64 - 5 and saturated past 2^64 - 1, silently.
  const std::string isam = scratch.write("g.isam", "EDGE2 0 1 1 0 0 1 0 0 1 0 1\n");
  expectRefused(runSemslam("convert isam " + isam + " --max-steps -5 --out " + scratch.path("m.jsonl")), "--max-steps");
  expectRefused(runSemslam("convert isam " + isam + " --max-steps 99999999999999999999999 --out " +
                           scratch.path("m.jsonl")),
                "2^64 - 1");
}

TEST(HostileCli, AnUnassignedRateWeightThatIsNotAPositiveNumberIsRefused) {
  const semslam::test::TempDir scratch;
  const std::string log = scratch.path("a.jsonl");
  ASSERT_EQ(runSemslam("simulate semantic --steps 3 --out " + log).exitCode, 0);
  for (const std::string value : {"0", "-1", "inf", "1e400", "abc"}) {
    expectRefused(runSemslam("run --method mm-nh --in " + log + " --out " + scratch.path("r") +
                             " --unassigned-rate-weight " + value),
                  "--unassigned-rate-weight");
  }
  expectRefused(runSemslam("run --method mm-nh --in " + log + " --out " + scratch.path("r") +
                           " --unassigned-rate-weight nan"),
                "prior weight must be positive and finite");
  EXPECT_FALSE(fs::exists(scratch.path("r")));
}

TEST(HostileCli, AnUnassignedRateMemoryBelowOneStepOrWithoutAnEstimatedRateIsRefused) {
  const semslam::test::TempDir scratch;
  const std::string log = scratch.path("a.jsonl");
  ASSERT_EQ(runSemslam("simulate semantic --steps 3 --out " + log).exitCode, 0);
  const std::string run = "run --method mm-nh --in " + log + " --out " + scratch.path("r");
  for (const std::string value : {"0", "0.5", "-1", "inf", "1e400", "abc"}) {
    expectRefused(runSemslam(run + " --unassigned-rate-weight 10 --unassigned-rate-memory " + value),
                  "--unassigned-rate-memory");
  }
  expectRefused(runSemslam(run + " --unassigned-rate-weight 10 --unassigned-rate-memory nan"),
                "memory must be finite and at least 1");
  expectRefused(runSemslam(run + " --unassigned-rate-memory 50"), "needs an estimated rate");
  EXPECT_FALSE(fs::exists(scratch.path("r")));
  EXPECT_EQ(runSemslam(run + " --unassigned-rate-weight 10 --unassigned-rate-memory 50 --quiet").exitCode, 0);
}

TEST(HostileCli, IntegersAreDecimalNeverOctalOrHexadecimal) {
  // CLI11 reads integers with strtoll(..., 0): "--seed 0467" became seed 311 and "--steps 010" 8 steps, silently
  // (found by the options fuzz harness).
  const semslam::test::TempDir scratch;
  const CommandResult ok = runSemslam("simulate semantic --seed 0467 --steps 010 --out " + scratch.path("a.jsonl"));
  EXPECT_EQ(ok.exitCode, 0) << ok.output;
  EXPECT_NE(ok.output.find("(10 steps of 1 m"), std::string::npos) << ok.output;
  EXPECT_NE(ok.output.find("seed 467)"), std::string::npos) << ok.output;
  expectRefused(runSemslam("simulate semantic --steps 0x10 --out " + scratch.path("b.jsonl")), "decimal whole number");
  expectRefused(runSemslam("simulate semantic --seed 0x10 --out " + scratch.path("b.jsonl")), "--seed");
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

// A two-step log (header, a first step, a second with odometry and a detection) whose second step's line is 3.
std::string logWithSecondStep(const std::string& increment, const std::string& geometry) {
  return R"({"format":"semslam-log","version":1,"dimension":2,"classes":3,"semantic":"label",)"
         R"("classifier":{"kind":"categorical","misclassification":0.1},"sensor":{"kind":"range-bearing"},)"
         R"("initial_pose":{"mean":[0,0,0],"covariance":[[1e-4,0,0],[0,1e-4,0],[0,0,1e-6]]}})"
         "\n"
         R"({"time":0,"detections":[{"geometry":[2,0.5],"covariance":[[0.01,0],[0,0.001]],"label":1,"truth":0}]})"
         "\n"
         R"({"time":1,"odometry":{"increment":)" + increment +
         R"(,"covariance":[[0.01,0,0],[0,0.01,0],[0,0,0.001]]},"detections":[{"geometry":)" + geometry +
         R"(,"covariance":[[0.01,0],[0,0.001]],"label":1,"truth":0}]})"
         "\n";
}

TEST(HostileCli, FiniteButHugeNumbersInALogExitTwoNamingTheLine) {
  // 1e308 in an odometry or a detection overflowed in the solver: exit 2 without a line, or exit 1
  // ("range-bearing: the point is at the sensor") for a range of 1e-300.
  const semslam::test::TempDir scratch;
  const std::string good = scratch.write("good.jsonl", logWithSecondStep("[1,0,0.1]", "[1.5,0.9]"));
  EXPECT_EQ(runSemslam("run --quiet --method known --in " + good + " --out " + scratch.path("ok")).exitCode, 0);
  struct Case {
    std::string increment, geometry, problem;
  };
  for (const Case& c : std::vector<Case>{{"[1e308,0,0.1]", "[1.5,0.9]", "odometry.increment[0]: number 1e+308 is too large"},
                                         {"[1,0,-1e200]", "[1.5,0.9]", "odometry.increment[2]: number -1e+200 is too large"},
                                         {"[1,0,0.1]", "[1e308,0.9]", "detections[0].geometry[0]: number 1e+308 is too large"},
                                         {"[1,0,0.1]", "[1e-300,0.9]", "detections[0].geometry: the range must be at least 1e-6"}}) {
    const std::string log = scratch.write("huge.jsonl", logWithSecondStep(c.increment, c.geometry));
    for (const char* method : {"known", "mm-nh"}) {
      const std::string out = scratch.path(std::string("r-") + method);
      expectRefused(runSemslam("run --quiet --method " + std::string(method) + " --in " + log + " --out " + out),
                    log + ":3: " + c.problem);
      EXPECT_FALSE(fs::exists(out));
    }
  }
}

// A log with a map prior (the hybrid belief needs one) whose first detection has the covariance `covariance`.
std::string logWithFirstDetectionCovariance(const std::string& covariance) {
  return R"({"format":"semslam-log","version":1,"dimension":2,"classes":2,"semantic":"probabilities",)"
         R"("classifier":{"kind":"categorical","misclassification":0.1},"sensor":{"kind":"range-bearing"},)"
         R"("initial_pose":{"mean":[0,0,0],"covariance":[[1e-4,0,0],[0,1e-4,0],[0,0,1e-6]]},)"
         R"("landmark_priors":[{"id":7,"mean":[4.0,2.0],"covariance":[[0.25,0.0],[0.0,0.25]]}],)"
         R"("landmark_truth":[{"id":7,"class":1,"position":[4.1,1.9]}]})"
         "\n"
         R"({"time":0,"detections":[{"geometry":[4.47,0.46],"covariance":)" + covariance +
         R"(,"probabilities":[0.2,0.8],"truth":7}]})"
         "\n"
         R"({"time":0.5,"odometry":{"increment":[0.5,0.0,0.05],"covariance":[[0.0025,0,0],[0,0.0025,0],[0,0,0.0004]]},)"
         R"("detections":[{"geometry":[3.89,0.46],"covariance":[[0.01,0],[0,0.0025]],"probabilities":[0.1,0.9],)"
         R"("truth":7}]})"
         "\n";
}

TEST(HostileCli, ABadlyConditionedCovarianceIsRefusedAtItsLine) {
  // diag(1e-18, 1e18): each variance within the log's limits and positive definite to Cholesky, yet `run` stopped
  // without a line: the hybrid belief with "covariance is not positive definite" (a rotated copy of it), paper B's
  // methods with "the system cannot be solved". Now an input error at the line, exit 2, for every method.
  const semslam::test::TempDir scratch;
  const std::string good = scratch.write("good.jsonl", logWithFirstDetectionCovariance("[[0.01,0],[0,0.0025]]"));
  const std::string bad = scratch.write("bad.jsonl", logWithFirstDetectionCovariance("[[1e-18,0],[0,1e18]]"));
  for (const char* method : {"known", "mm-nh", "hybrid"}) {
    const std::string out = scratch.path(std::string("r-") + method);
    EXPECT_EQ(runSemslam("run --quiet --method " + std::string(method) + " --in " + good + " --out " + out).exitCode, 0)
        << method;
    const std::string refused = scratch.path(std::string("x-") + method);
    expectRefused(runSemslam("run --quiet --method " + std::string(method) + " --in " + bad + " --out " + refused),
                  bad + ":2: detections[0].covariance: badly conditioned: eigenvalues from 1e-18 to 1e+18");
    EXPECT_FALSE(fs::exists(refused));
  }
}

TEST(HostileCli, ConvertRefusesMoreClassesThanALogMayHoldBeforeReading) {
  // --classes 100000 allocated a 10^5 x 10^5 confusion matrix before any data: std::bad_alloc, exit 1.
  const semslam::test::TempDir scratch;
  const std::string isam = scratch.write("g.isam", "EDGE2 0 1 1 0 0 1 0 0 1 0 1\n");
  expectRefused(runSemslam("convert isam " + isam + " --classes 100000 --out " + scratch.path("x.jsonl")),
                "--classes must be in [1, 2048], got 100000");
  EXPECT_FALSE(fs::exists(scratch.path("x.jsonl")));
}

TEST(HostileCli, ConvertRefusesADatasetWhoseLogTheReaderWouldRefuse) {
  // The writer refused the log with std::invalid_argument after the conversion: exit 1. Now an input error naming
  // the dataset's file and line that made the refused part, the log's step and the field.
  const semslam::test::TempDir scratch;
  const std::string isam = scratch.write("g.isam", "EDGE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE2 1 2 1e308 0 0 1 0 0 1 0 1\n");
  expectRefused(runSemslam("convert isam " + isam + " --out " + scratch.path("x.jsonl")),
                isam + ":2: the log made from it would be refused (log step 2): odometry.increment[0]: number 1e+308 is "
                       "too large");
  const std::string fine = scratch.write("f.isam", "EDGE2 0 1 1 0 0 1 0 0 1 0 1\n");
  expectRefused(runSemslam("convert isam " + fine + " --initial-pose-sigma 1e-12,1,1 --out " + scratch.path("x.jsonl")),
                "--initial-pose-sigma values must be in [1e-9, 1e9], got 1e-12");
  EXPECT_FALSE(fs::exists(scratch.path("x.jsonl")));
}

}  // namespace
