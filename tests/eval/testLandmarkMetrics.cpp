// Landmark metrics: count error, RMSE of matched positions after the trajectory's alignment, class accuracy.

#include <gtest/gtest.h>

#include <cmath>

#include "semslam/eval/LandmarkMetrics.h"
#include "semslam/eval/PlanarAlignment.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

LandmarkTruth truth(int id, int classIndex, const LandmarkState& state) { return {id, classIndex, state}; }

EstimatedLandmark estimated(int id, const LandmarkState& state, Vector probabilities = Vector()) {
  return {id, state, std::move(probabilities)};
}

LandmarkMatching matching(std::vector<LandmarkPair> pairs) {
  LandmarkMatching m;
  m.pairs = std::move(pairs);
  return m;
}

TEST(LandmarkMetrics, CountErrorRmseAndClassAccuracyWithoutAlignment) {
  const std::vector<LandmarkTruth> t = {truth(0, 1, Point2(0, 0)), truth(1, 0, Point2(5, 0)),
                                        truth(2, 2, Point2(0, 5))};
  const std::vector<EstimatedLandmark> e = {
      estimated(10, Point2(0, 1), Vector3(0.1, 0.8, 0.1)),   // matched to 0: error 1, class right
      estimated(11, Point2(5, -2), Vector3(0.2, 0.7, 0.1)),  // matched to 1: error 2, class wrong
      estimated(12, Point2(9, 9)),                           // unmatched (e.g. made of clutter)
      estimated(13, Point2(1, 5)),                           // matched to 2: error 1, no class estimate
  };
  const LandmarkMetrics m = evaluateLandmarks(e, t, matching({{10, 0, 4}, {11, 1, 2}, {13, 2, 1}}));
  EXPECT_EQ(m.estimated, 4u);
  EXPECT_EQ(m.truth, 3u);
  EXPECT_EQ(m.countError, 1);
  EXPECT_EQ(m.matched, 3u);
  EXPECT_EQ(m.positionErrors, (std::vector<double>{1.0, 2.0, 1.0}));
  EXPECT_DOUBLE_EQ(m.positionRmse, std::sqrt(6.0 / 3.0));
  EXPECT_EQ(m.classesCompared, 2u);
  EXPECT_EQ(m.classesCorrect, 1u);
  EXPECT_DOUBLE_EQ(m.classAccuracy, 0.5);
}

TEST(LandmarkMetrics, UsesTheTrajectoryAlignment) {
  // The estimate lives in a frame rotated and shifted by A⁻¹; the trajectory's alignment A brings it back.
  const SE2 a(2.0, -1.0, 0.8);
  const std::vector<LandmarkTruth> t = {truth(0, -1, Point2(3, 4)), truth(1, -1, SE2(-2, 1, 0.5))};
  const std::vector<EstimatedLandmark> e = {estimated(5, Point2(a.transformTo(Point2(3, 4)))),
                                            estimated(6, a.inverse() * SE2(-2, 1, 0.5))};
  Eigen::Matrix2Xd x(2, 3), y(2, 3);
  x << 0, 1, 0, 0, 0, 1;
  for (int i = 0; i < 3; ++i) y.col(i) = a.transformFrom(x.col(i));
  const SimilarityTransform alignment = planarRigidAlignment(x, y);
  const LandmarkMatching pairs = matching({{5, 0, 1}, {6, 1, 1}});

  const LandmarkMetrics aligned = evaluateLandmarks(e, t, pairs, alignment);
  EXPECT_LT(aligned.positionRmse, 1e-12);
  EXPECT_TRUE(std::isnan(aligned.classAccuracy));  // no class information on either side
  const LandmarkMetrics raw = evaluateLandmarks(e, t, pairs);
  EXPECT_GT(raw.positionRmse, 1.0);
}

TEST(LandmarkMetrics, SpatialLandmarks) {
  const std::vector<LandmarkTruth> t = {truth(0, 0, Point3(1, 2, 3))};
  const std::vector<EstimatedLandmark> e = {estimated(0, SE3(SO3(), Point3(1, 2, 5)), Vector2(0.6, 0.4))};
  const LandmarkMetrics m = evaluateLandmarks(e, t, matching({{0, 0, 3}}));
  EXPECT_DOUBLE_EQ(m.positionRmse, 2.0);
  EXPECT_DOUBLE_EQ(m.classAccuracy, 1.0);
}

TEST(LandmarkMetrics, NothingMatched) {
  const LandmarkMetrics m = evaluateLandmarks({estimated(1, Point2(0, 0))}, {}, LandmarkMatching{});
  EXPECT_EQ(m.countError, 1);
  EXPECT_EQ(m.matched, 0u);
  EXPECT_TRUE(std::isnan(m.positionRmse));
  EXPECT_TRUE(std::isnan(m.classAccuracy));
}

TEST(LandmarkMetrics, HelpersAndInvalidInput) {
  EXPECT_EQ(mostProbableClass(Vector3(0.2, 0.4, 0.4)), 1);  // first maximum
  EXPECT_EQ(mostProbableClass(Vector()), -1);
  EXPECT_EQ(landmarkPosition(SE2(1, 2, 3)), Vector(Vector2(1, 2)));
  EXPECT_THROW(evaluateLandmarks({estimated(1, Point2(0, 0)), estimated(1, Point2(1, 0))}, {}, LandmarkMatching{}),
               InputError);
  EXPECT_THROW(evaluateLandmarks({estimated(1, Point2(0, 0))}, {truth(0, 0, Point3(0, 0, 0))},
                                 matching({{1, 0, 1}})),
               InputError);
}

}  // namespace
}  // namespace semslam
