// runOutputFrom writes the truth wherever the log has it: a log with true poses on some steps only still gets a
// truth trajectory, holding exactly those steps at their times (python/plot_run.py and plot_methods.py draw it).

#include <gtest/gtest.h>

#include "semslam/io/RunOutputFromResult.h"

namespace semslam {
namespace {

MeasurementLog logWithTruthOn(const std::vector<bool>& hasTruth) {
  MeasurementLog log;
  log.header.dimension = 2;
  for (std::size_t k = 0; k < hasTruth.size(); ++k) {
    TimeStep step;
    step.time = 10.0 + static_cast<double>(k);
    if (hasTruth[k]) step.truePose = Pose(SE2(static_cast<double>(k), 0.5, 0.0));
    log.steps.push_back(step);
  }
  return log;
}

RunResult estimateFor(const MeasurementLog& log) {
  RunResult result;
  for (std::size_t k = 0; k < log.steps.size(); ++k) result.poses.push_back(Pose(SE2(static_cast<double>(k), 0, 0)));
  return result;
}

TEST(RunOutputTruth, PartialTruthIsKeptAtTheStepsThatHaveIt) {
  const MeasurementLog log = logWithTruthOn({true, true, false, true, false});
  const RunOutput output = runOutputFrom(log, estimateFor(log), {});
  ASSERT_EQ(output.trajectory.size(), 5u);
  ASSERT_TRUE(output.truth.has_value());
  ASSERT_EQ(output.truth->size(), 3u);
  EXPECT_EQ(output.truth->timestamps(), (std::vector<double>{10.0, 11.0, 13.0}));
  EXPECT_DOUBLE_EQ(output.truth->poses()[2].translation().x(), 3.0);
}

TEST(RunOutputTruth, NoTruthAnywhereGivesNoTruthTrajectory) {
  const MeasurementLog log = logWithTruthOn({false, false, false});
  EXPECT_FALSE(runOutputFrom(log, estimateFor(log), {}).truth.has_value());
}

TEST(RunOutputTruth, FullTruthHasEveryStep) {
  const MeasurementLog log = logWithTruthOn({true, true, true});
  const RunOutput output = runOutputFrom(log, estimateFor(log), {});
  ASSERT_TRUE(output.truth.has_value());
  EXPECT_EQ(output.truth->timestamps(), output.trajectory.timestamps());
}

}  // namespace
}  // namespace semslam
