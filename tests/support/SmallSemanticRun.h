#pragma once
// What the tests of MethodOptions' back-end settings share (tests/run/testSwitchRounds.cpp,
// testRelinearization.cpp): a small seeded planar semantic log, and the check that two runs end on the same
// trajectory bit for bit.

#include <gtest/gtest.h>

#include <random>
#include <variant>

#include "semslam/run/RunMethod.h"
#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"

namespace semslam::test {

/// 30 steps of a generated path, 6 landmarks of 3 classes, 10 % misclassification, seed 5.
inline MeasurementLog smallSemanticLog() {
  PathOptions path;
  path.steps = 30;
  std::mt19937 rng(5);
  SemanticSimOptions options;
  options.classes = 3;
  options.landmarks = 6;
  options.misclassification = 0.1;
  return simulateSemantic(generatePath(path, rng), options, 5);
}

/// Both runs' final poses (SE2) equal to the last bit.
inline void expectSamePlanarTrajectory(const MethodRun& a, const MethodRun& b) {
  ASSERT_EQ(a.result.poses.size(), b.result.poses.size());
  for (std::size_t k = 0; k < a.result.poses.size(); ++k) {
    const auto& pa = std::get<SE2>(a.result.poses[k]);
    const auto& pb = std::get<SE2>(b.result.poses[k]);
    EXPECT_EQ(pa.translation().x(), pb.translation().x()) << "pose " << k;
    EXPECT_EQ(pa.translation().y(), pb.translation().y()) << "pose " << k;
    EXPECT_EQ(pa.theta(), pb.theta()) << "pose " << k;
  }
}

}  // namespace semslam::test
