// iSAM files have no vertex records: poses are chained from odometry, landmarks placed by their first observation.

#include <gtest/gtest.h>

#include "IoTesting.h"
#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/io/PoseGraphFile.h"

namespace semslam {
namespace {

using test::TempDir;

TEST(IsamInitialisation, ChainsOdometryAndPlacesLandmarks) {
  TempDir dir;
  const std::string file = dir.write("three.txt",
                                     "ODOMETRY 3 4 1 0 0.5  10 0 0 10 0 20\n"
                                     "EDGE2 4 5 2 1 -0.25  10 1 2 10 3 20\n"
                                     "LANDMARK 5 0 1 1  5 0.5 5\n");
  const PoseGraphFile graph = readPoseGraph(file, GraphFormat::Isam);
  ASSERT_EQ(graph.initial.size(), 4u);
  ASSERT_EQ(graph.factors.size(), 3u);
  EXPECT_EQ(graph.firstPose, poseKey(3));
  EXPECT_TRUE(graph.fixed.empty());

  const SE2 x3;  // the first pose of the first edge is the identity
  const SE2 x4 = x3 * SE2(1, 0, 0.5);
  const SE2 x5 = x4 * SE2(2, 1, -0.25);
  EXPECT_TRUE(graph.initial.at<SE2>(poseKey(3)).equals(x3, 0.0));
  EXPECT_TRUE(graph.initial.at<SE2>(poseKey(4)).equals(x4, 1e-15));
  EXPECT_TRUE(graph.initial.at<SE2>(poseKey(5)).equals(x5, 1e-15));
  EXPECT_TRUE(graph.initial.at<Point2>(landmarkKey(0)).isApprox(x5.transformFrom(Point2(1, 1)), 1e-15));

  // The measurements hold exactly, so the chained initial estimate has zero error.
  EXPECT_NEAR(graph.factors.chi2(graph.initial), 0.0, 1e-20);

  // Square-root information, upper triangular, row-major.
  const auto& second = dynamic_cast<const BetweenFactor<SE2>&>(*graph.factors[1]);
  Matrix3 R;
  R << 10, 1, 2, 0, 10, 3, 0, 0, 20;
  EXPECT_EQ(second.noiseModel()->sqrtInformation(), Matrix(R));
  EXPECT_TRUE(second.noiseModel()->information().isApprox(R.transpose() * R, 1e-15));
  const auto& landmark = dynamic_cast<const RelativePointFactor<SE2, Point2>&>(*graph.factors[2]);
  Matrix2 S;
  S << 5, 0.5, 0, 5;
  EXPECT_EQ(landmark.noiseModel()->sqrtInformation(), Matrix(S));
  EXPECT_EQ(landmark.keys(), (std::vector<Key>{poseKey(5), landmarkKey(0)}));
}

TEST(IsamInitialisation, LoopClosuresAndBackwardChaining) {
  TempDir dir;
  const std::string file = dir.write("loop.txt",
                                     "EDGE2 0 1 1 0 0 1 0 0 1 0 1\n"
                                     "EDGE2 1 2 1 0 1.5 1 0 0 1 0 1\n"
                                     "EDGE2 2 0 3 3 3 1 0 0 1 0 1\n"    // loop closure: both poses known
                                     "EDGE2 7 2 0 1 0.1 1 0 0 1 0 1\n"  // x7 new, x2 known: x7 = x2 · z⁻¹
                                     "LANDMARK 1 3 2 0 1 0 1\n"
                                     "LANDMARK 2 3 9 9 1 0 1\n");  // second observation: no new value
  const PoseGraphFile graph = readPoseGraph(file, GraphFormat::Isam);
  EXPECT_EQ(graph.initial.size(), 5u);
  EXPECT_EQ(graph.factors.size(), 6u);
  const SE2 x2 = SE2(1, 0, 0) * SE2(1, 0, 1.5);
  EXPECT_TRUE(graph.initial.at<SE2>(poseKey(2)).equals(x2, 1e-15));
  EXPECT_TRUE(graph.initial.at<SE2>(poseKey(7)).equals(x2 * SE2(0, 1, 0.1).inverse(), 1e-15));
  EXPECT_TRUE(graph.initial.at<Point2>(landmarkKey(3)).isApprox(Point2(3, 0), 1e-15));
}

}  // namespace
}  // namespace semslam
