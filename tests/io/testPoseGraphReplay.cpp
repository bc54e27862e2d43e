// PoseGraphReplay: a pose graph split into online steps (pose-key order, each pose with its edges to earlier poses,
// landmarks entering with their first observation), new values initialised from the current estimate.

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "IoTesting.h"
#include "semslam/io/PoseGraphAnchor.h"
#include "semslam/io/PoseGraphReplay.h"
#include "support/TestData.h"

namespace semslam {
namespace {

using test::TempDir;

TEST(PoseGraphReplay, IsamStepsChainOdometryFromTheCurrentEstimateAndAddLandmarksAtFirstSight) {
  TempDir dir;
  // Poses 0..3; a loop closure 3-0 (given from the later pose) and a landmark first seen from pose 1.
  const std::string file = dir.write("loop.txt",
                                     "ODOMETRY 0 1 1 0 0.5  10 0 0 10 0 20\n"
                                     "ODOMETRY 1 2 1 0 0.5  10 0 0 10 0 20\n"
                                     "LANDMARK 1 7 2 1  5 0 5\n"
                                     "ODOMETRY 2 3 1 0 0.5  10 0 0 10 0 20\n"
                                     "LANDMARK 3 7 0.5 -1  5 0 5\n"
                                     "EDGE2 3 0 -1 1 1.5  10 0 0 10 0 20\n");
  const PoseGraphFile graph = readPoseGraph(file, GraphFormat::Isam);
  const PoseGraphReplay replay(graph);
  ASSERT_EQ(replay.size(), 4u);

  Values current;
  ReplayStep step = replay.step(0, current);
  EXPECT_EQ(step.pose, poseKey(0));
  EXPECT_EQ(step.factors.size(), 1u);  // the anchor prior only
  EXPECT_EQ(step.values.size(), 1u);
  current.insert(step.values);

  // Step 1 chains from the *current* estimate of x0, which a smoother may have moved.
  const SE2 moved(0.3, -0.2, 0.1);
  current.update(poseKey(0), moved);
  step = replay.step(1, current);
  EXPECT_EQ(step.pose, poseKey(1));
  EXPECT_EQ(step.factors.size(), 2u);  // odometry 0-1 and the landmark's first observation
  ASSERT_TRUE(step.values.exists(landmarkKey(7)));
  const SE2 x1 = moved * SE2(1, 0, 0.5);
  EXPECT_TRUE(step.values.at<SE2>(poseKey(1)).equals(x1, 1e-15));
  EXPECT_TRUE(step.values.at<Point2>(landmarkKey(7)).isApprox(x1.transformFrom(Point2(2, 1)), 1e-15));
  current.insert(step.values);

  step = replay.step(2, current);
  EXPECT_EQ(step.factors.size(), 1u);
  current.insert(step.values);
  step = replay.step(3, current);
  EXPECT_EQ(step.factors.size(), 3u);  // odometry 2-3, the second observation, the loop closure
  EXPECT_EQ(step.values.size(), 1u);   // the landmark is known already
  EXPECT_THROW(replay.step(4, current), std::out_of_range);
}

TEST(PoseGraphReplay, EveryFactorEntersOnceWhenAllItsVariablesAreKnown) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/intel/originalDataset/intel.g2o");
  const PoseGraphFile graph = readPoseGraph(path.string(), GraphFormat::G2o);
  const PoseGraphReplay replay(graph);
  EXPECT_EQ(replay.size(), graph.initial.size());
  EXPECT_EQ(replay.graph().size(), graph.factors.size() + anchorFactors(graph).size());
  std::set<const Factor*> seen;
  Values current;
  Key previous = 0;
  for (std::size_t k = 0; k < replay.size(); ++k) {
    const ReplayStep step = replay.step(k, current);
    if (k > 0) EXPECT_LT(previous, step.pose);
    previous = step.pose;
    EXPECT_TRUE(step.values.exists(step.pose));
    current.insert(step.values);
    for (const auto& factor : step.factors) {
      EXPECT_TRUE(seen.insert(factor.get()).second);
      for (Key key : factor->keys()) EXPECT_TRUE(current.exists(key));
      bool touchesNewest = false;
      for (Key key : factor->keys()) touchesNewest = touchesNewest || key == step.pose;
      EXPECT_TRUE(touchesNewest);
    }
  }
  EXPECT_EQ(seen.size(), replay.graph().size());
}

}  // namespace
}  // namespace semslam
