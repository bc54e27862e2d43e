// `semslam convert` and `semslam check --residuals` from the command line.

#include <gtest/gtest.h>

#include "io/ConverterTesting.h"
#include "support/RunCommand.h"
#include "support/TestData.h"

using semslam::test::runSemslam;
using semslam::test::TempDir;

TEST(ConvertCommand, WritesALogTheCheckerAcceptsAndReportsResiduals) {
  SEMSLAM_REQUIRE_DATA(path, "isam/cityTrees10000.txt");
  TempDir dir;
  const std::string out = dir.path("trees.jsonl");
  const auto run = runSemslam("convert isam " + path.string() + " --out " + out +
                              " --classes 3 --misclassification 0.1 --seed 4 --keyframe-period 10 --max-steps 50"
                              " --initial-pose-sigma 0.01,0.01,0.001 --map-prior 2");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("wrote " + out + ": isam, 50 steps"), std::string::npos) << run.output;
  const semslam::MeasurementLog log = semslam::readMeasurementLog(out);
  EXPECT_EQ(log.steps.size(), 50u);
  EXPECT_EQ(log.steps[1].time, 10.0);
  EXPECT_EQ(log.header.classes, 3);
  EXPECT_EQ(log.header.landmarkPriors.size(), 100u);
  EXPECT_DOUBLE_EQ(log.header.initialPose->covariance(2, 2), 1e-6);

  // Same seed, same bytes, run to run.
  const std::string again = dir.path("again.jsonl");
  ASSERT_EQ(runSemslam("convert isam " + path.string() + " --out " + again +
                       " --classes 3 --misclassification 0.1 --seed 4 --keyframe-period 10 --max-steps 50"
                       " --initial-pose-sigma 0.01,0.01,0.001 --map-prior 2")
                .exitCode,
            0);
  EXPECT_TRUE(semslam::test::readText(out) == semslam::test::readText(again));

  const auto check = runSemslam("check " + out + " --residuals");
  ASSERT_EQ(check.exitCode, 0) << check.output;
  EXPECT_NE(check.output.find("residuals against the ground truth"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("odometry:"), std::string::npos) << check.output;
}

TEST(ConvertCommand, BadArgumentsExitWithTwo) {
  TempDir dir;
  const std::string out = dir.path("x.jsonl");
  const auto unknown = runSemslam("convert kitti /nowhere --out " + out);
  EXPECT_EQ(unknown.exitCode, 2) << unknown.output;
  const auto missing = runSemslam("convert utias-lost-in-the-woods " + dir.path("absent") + " --out " + out);
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  EXPECT_NE(missing.output.find("not a folder"), std::string::npos) << missing.output;
  const auto robot = runSemslam("convert isam " + dir.path("absent.txt") + " --robot 2 --out " + out);
  EXPECT_EQ(robot.exitCode, 2) << robot.output;
  EXPECT_NE(robot.output.find("--robot applies to mrclam only"), std::string::npos) << robot.output;
  const auto sigmas = runSemslam("convert isam " + dir.path("absent.txt") + " --initial-pose-sigma 1,2 --out " + out);
  EXPECT_EQ(sigmas.exitCode, 2) << sigmas.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}
