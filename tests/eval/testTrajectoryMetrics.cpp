// SE(2) alignment (Umeyama restricted to rotations about z) and the trajectory metrics of metrics.json.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "semslam/eval/PlanarAlignment.h"
#include "semslam/eval/TrajectoryMetrics.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

std::vector<SE2> randomPlanarTrajectory(std::mt19937& rng, int n) {
  std::normal_distribution<double> step(0.0, 1.0), turn(0.0, 0.3);
  std::vector<SE2> poses{SE2(0.0, 0.0, 0.0)};
  for (int i = 1; i < n; ++i) poses.push_back(poses.back() * SE2(1.0 + 0.2 * step(rng), 0.1 * step(rng), turn(rng)));
  return poses;
}

TEST(PlanarAlignment, RecoversAKnownPlanarTransformExactly) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0), angle(-std::numbers::pi, std::numbers::pi);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 2 + trial;
    const double phi = angle(rng);
    const Vector2 t(coordinate(rng), coordinate(rng));
    const Matrix2 r = SO2(phi).matrix();
    Eigen::Matrix2Xd x(2, n);
    for (int i = 0; i < n; ++i) x.col(i) = Vector2(coordinate(rng), coordinate(rng));
    const Eigen::Matrix2Xd y = (r * x).colwise() + t;
    const SimilarityTransform s = planarRigidAlignment(x, y);
    EXPECT_LT((s.rotation.topLeftCorner<2, 2>() - r).cwiseAbs().maxCoeff(), 1e-13) << trial;
    EXPECT_LT((s.translation.head<2>() - t).cwiseAbs().maxCoeff(), 1e-11) << trial;
    EXPECT_EQ(s.rotation(2, 2), 1.0);
    EXPECT_EQ(s.rotation(0, 2), 0.0);
    EXPECT_EQ(s.translation.z(), 0.0);
    EXPECT_EQ(s.scale, 1.0);
  }
}

TEST(PlanarAlignment, TwoPointsAndCollinearPointsSuffice) {
  const double phi = 2.5;
  const Vector2 t(3.0, -1.0);
  Eigen::Matrix2Xd x(2, 4);
  x << 0, 1, 2, 5,  //
      0, 1, 2, 5;   // all on one line
  const Eigen::Matrix2Xd y = (SO2(phi).matrix() * x).colwise() + t;
  const SimilarityTransform s = planarRigidAlignment(x, y);
  EXPECT_NEAR(std::atan2(s.rotation(1, 0), s.rotation(0, 0)), phi, 1e-14);
  EXPECT_LT((s.translation.head<2>() - t).norm(), 1e-13);
  const SimilarityTransform two = planarRigidAlignment(x.leftCols(2), y.leftCols(2));
  EXPECT_NEAR(std::atan2(two.rotation(1, 0), two.rotation(0, 0)), phi, 1e-14);
}

TEST(PlanarAlignment, AgreesWithThreeDimensionalUmeyamaOnPlanarPoints) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::Matrix2Xd x(2, 30), y(2, 30);
  for (int i = 0; i < 30; ++i) {
    x.col(i) = Vector2(5 * noise(rng), 5 * noise(rng));
    y.col(i) = SO2(0.7).rotate(x.col(i)) + Vector2(1.0, 2.0) + 0.1 * Vector2(noise(rng), noise(rng));
  }
  Eigen::Matrix3Xd x3 = Eigen::Matrix3Xd::Zero(3, 30), y3 = Eigen::Matrix3Xd::Zero(3, 30);
  x3.topRows<2>() = x;
  y3.topRows<2>() = y;
  const SimilarityTransform planar = planarRigidAlignment(x, y);
  const SimilarityTransform spatial = umeyamaAlignment(x3, y3, false);
  EXPECT_LT((planar.rotation - spatial.rotation).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((planar.translation - spatial.translation).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(PlanarAlignment, DegenerateInputThrows) {
  Eigen::Matrix2Xd one(2, 1);
  one << 1, 2;
  EXPECT_THROW(planarRigidAlignment(one, one), InputError);
  Eigen::Matrix2Xd same(2, 3);
  same << 1, 1, 1, 2, 2, 2;
  EXPECT_THROW(planarRigidAlignment(same, same), InputError);
  EXPECT_THROW(planarRigidAlignment(Eigen::Matrix2Xd(2, 2), Eigen::Matrix2Xd(2, 3)), InputError);
  // The mirror image of an isotropic point set: every rotation fits it equally well.
  Eigen::Matrix2Xd original(2, 4), mirrored(2, 4);
  original << 1, -1, 0, 0,  //
      0, 0, 1, -1;
  mirrored << 1, -1, 0, 0,  //
      0, 0, -1, 1;
  EXPECT_THROW(planarRigidAlignment(original, mirrored), InputError);
  EXPECT_NO_THROW(planarRigidAlignment(original, original));
}

TEST(TrajectoryMetrics, AlignedPlanarTrajectoryHasZeroError) {
  std::mt19937 rng(5);
  const std::vector<SE2> truth = randomPlanarTrajectory(rng, 40);
  const SE2 offset(10.0, -4.0, 1.1);
  std::vector<SE2> estimate;
  for (const SE2& pose : truth) estimate.push_back(offset * pose);  // the same trajectory in another frame
  const TrajectoryErrors e = evaluateTrajectoryErrors(estimate, truth);
  EXPECT_TRUE(e.aligned);
  EXPECT_EQ(e.dimension, 2);
  EXPECT_LT(e.translation.max, 1e-11);
  EXPECT_LT(e.rotation.max, 1e-12);
  // The alignment is offset⁻¹.
  const SE2 inverse = offset.inverse();
  EXPECT_NEAR(std::atan2(e.alignment.rotation(1, 0), e.alignment.rotation(0, 0)), inverse.theta(), 1e-13);
  EXPECT_LT((e.alignment.translation.head<2>() - inverse.translation()).norm(), 1e-11);

  const TrajectoryErrors raw = evaluateTrajectoryErrors(estimate, truth, false);
  EXPECT_FALSE(raw.aligned);
  EXPECT_NEAR(raw.rotation.max, 1.1, 1e-12);
  EXPECT_NEAR(raw.rotation.min, 1.1, 1e-12);
}

TEST(TrajectoryMetrics, KnownErrorsAndStatistics) {
  const std::vector<SE2> truth = {SE2(0, 0, 0), SE2(1, 0, 0), SE2(2, 0, 0), SE2(3, 0, 0)};
  // Position errors 1, 0, 2, 0 along y (no alignment); heading errors 0.1, -0.2, 0.3, 0.
  const std::vector<SE2> estimate = {SE2(0, 1, 0.1), SE2(1, 0, -0.2), SE2(2, 2, 0.3), SE2(3, 0, 0.0)};
  const TrajectoryErrors e = evaluateTrajectoryErrors(estimate, truth, false);
  EXPECT_DOUBLE_EQ(e.translation.max, 2.0);
  EXPECT_DOUBLE_EQ(e.translation.mean, 0.75);
  EXPECT_DOUBLE_EQ(e.translation.median, 0.5);
  EXPECT_DOUBLE_EQ(e.translation.rmse, std::sqrt(5.0 / 4.0));
  EXPECT_NEAR(e.rotation.max, 0.3, 1e-15);
  EXPECT_NEAR(e.rotation.mean, 0.15, 1e-15);
  EXPECT_NEAR(e.rotation.median, 0.15, 1e-15);
  EXPECT_NEAR(e.rotation.rmse, std::sqrt((0.01 + 0.04 + 0.09) / 4.0), 1e-15);
}

TEST(TrajectoryMetrics, RotationErrorWrapsAroundPi) {
  const std::vector<SE2> truth = {SE2(0, 0, -3.1), SE2(1, 0, 0)};
  const std::vector<SE2> estimate = {SE2(0, 0, 3.1), SE2(1, 0, 0)};
  const TrajectoryErrors e = evaluateTrajectoryErrors(estimate, truth, false);
  EXPECT_NEAR(e.rotationErrors[0], 2.0 * std::numbers::pi - 6.2, 1e-12);
}

TEST(TrajectoryMetrics, AlignedSpatialTrajectoryHasZeroError) {
  std::mt19937 rng(8);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<SE3> truth{SE3()};
  for (int i = 1; i < 30; ++i) {
    Vector6 xi;
    xi << 1.0, 0.2 * noise(rng), 0.2 * noise(rng), 0.1 * noise(rng), 0.1 * noise(rng), 0.3 * noise(rng);
    truth.push_back(truth.back() * SE3::Exp(xi));
  }
  Vector6 g;
  g << 4.0, -2.0, 7.0, 0.3, -0.5, 2.0;
  const SE3 offset = SE3::Exp(g);
  std::vector<SE3> estimate;
  for (const SE3& pose : truth) estimate.push_back(offset * pose);
  const TrajectoryErrors e = evaluateTrajectoryErrors(estimate, truth);
  EXPECT_EQ(e.dimension, 3);
  EXPECT_LT(e.translation.max, 1e-10);
  EXPECT_LT(e.rotation.max, 1e-10);
  EXPECT_LT((e.alignment.rotation - offset.inverse().rotation().matrix()).cwiseAbs().maxCoeff(), 1e-12);

  // Through the log's Pose variant, too.
  const std::vector<Pose> estimateVariant(estimate.begin(), estimate.end());
  const std::vector<Pose> truthVariant(truth.begin(), truth.end());
  EXPECT_LT(evaluateTrajectoryErrors(estimateVariant, truthVariant).translation.max, 1e-10);
}

TEST(TrajectoryMetrics, InvalidInputThrows) {
  EXPECT_THROW(evaluateTrajectoryErrors(std::vector<SE2>{}, std::vector<SE2>{}), InputError);
  EXPECT_THROW(evaluateTrajectoryErrors(std::vector<SE2>{SE2()}, std::vector<SE2>{SE2(), SE2()}), InputError);
  const std::vector<Pose> mixed = {SE2(), SE3()};
  const std::vector<Pose> planar = {SE2(), SE2(1, 0, 0)};
  EXPECT_THROW(evaluateTrajectoryErrors(mixed, planar), InputError);
  EXPECT_THROW(evaluateTrajectoryErrors(std::vector<SE2>{SE2(), SE2()}, std::vector<SE2>{SE2(), SE2()}), InputError);
}

}  // namespace
}  // namespace semslam
