// CartesianGateFactor: Jacobians, and agreement with the range-bearing measurement it re-expresses.

#include <gtest/gtest.h>

#include <random>

#include "semslam/hybrid/CartesianGateFactor.h"
#include "semslam/models/RangeBearingElevationSensor3.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/Sampling.h"
#include "support/FactorTesting.h"

using namespace semslam;

TEST(CartesianGateFactor, JacobiansAndZeroErrorAtTheMeasuredPoint) {
  std::mt19937 rng(2);
  const SE2 mount(0.2, 0.1, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    const SE2 robot(4 * uniform01(rng) - 2, 4 * uniform01(rng) - 2, 6 * uniform01(rng) - 3);
    const SE2 object(4 * uniform01(rng) - 2, 4 * uniform01(rng) - 2, 6 * uniform01(rng) - 3);
    const Vector2 rb = RangeBearingSensor2(mount).predict(robot, object.translation());
    const auto factor = CartesianGateFactor<SE2>::fromRangeBearing(poseKey(0), landmarkKey(0), rb,
                                                                  Vector2(0.1, 0.05).asDiagonal(), mount);
    Values values;
    values.insert(poseKey(0), robot);
    values.insert(landmarkKey(0), object);
    EXPECT_NEAR(factor->chi2(values), 0.0, 1e-16);
    values.update(landmarkKey(0), SE2(object.rotation(), object.translation() + Point2(0.3, -0.2)));
    test::expectJacobiansMatch(*factor, values, 1e-6);
  }
}

namespace {

SE3 level(const SE2& pose, double z = 0.0) {
  return SE3(SO3::fromAxisAngle(Vector3::UnitZ(), pose.theta()), Point3(pose.x(), pose.y(), z));
}

}  // namespace

TEST(CartesianGateFactor, RangeBearingElevationJacobiansAndZeroErrorAtTheMeasuredPoint) {
  std::mt19937 rng(5);
  const SE3 mount(SO3::fromAxisAngle(Vector3(0.2, -0.4, 1.0).normalized(), 0.3), Point3(0.2, 0.1, 0.5));
  const Matrix3 covariance = Vector3(0.1, 0.05, 0.02).asDiagonal();
  for (int trial = 0; trial < 20; ++trial) {
    const SE3 robot = SE3::Exp((Vector6() << uniform01(rng), uniform01(rng), uniform01(rng), 4 * uniform01(rng) - 2,
                                4 * uniform01(rng) - 2, uniform01(rng))
                                   .finished());
    const SE3 object = SE3::Exp((Vector6() << uniform01(rng), uniform01(rng), 3 * uniform01(rng) - 1.5,
                                 6 * uniform01(rng) - 3, 6 * uniform01(rng) - 3, 2 * uniform01(rng) - 1)
                                    .finished());
    const Vector3 rbe = RangeBearingElevationSensor3(mount).predict(robot, object.translation());
    const auto factor =
        CartesianGateFactor<SE3>::fromRangeBearingElevation(poseKey(0), landmarkKey(0), rbe, covariance, mount);
    Values values;
    values.insert(poseKey(0), robot);
    values.insert(landmarkKey(0), object);
    EXPECT_NEAR(factor->chi2(values), 0.0, 1e-14);
    values.update(landmarkKey(0), SE3(object.rotation(), object.translation() + Point3(0.3, -0.2, 0.1)));
    test::expectJacobiansMatch(*factor, values, 1e-6);
    const auto point = CartesianGateFactor<Point3>::fromRangeBearingElevation(poseKey(0), landmarkKey(1), rbe,
                                                                              covariance, mount);
    values.insert(landmarkKey(1), Point3(object.translation() + Point3(-0.1, 0.2, 0.3)));
    test::expectJacobiansMatch(*point, values, 1e-6);
  }
}

TEST(CartesianGateFactor, OnALevelDetectionThe3dGateIsThe2dGate) {
  // A level robot and sensor and a detection at zero elevation: the 3D factor's chi2 at any level configuration
  // is the 2D factor's (its z row has zero error there and is uncorrelated with x, y).
  std::mt19937 rng(7);
  const SE2 mount2(0.2, 0.1, 0.3);
  for (int trial = 0; trial < 10; ++trial) {
    const SE2 robot(4 * uniform01(rng) - 2, 4 * uniform01(rng) - 2, 6 * uniform01(rng) - 3);
    const SE2 object(4 * uniform01(rng) - 2, 4 * uniform01(rng) - 2, 6 * uniform01(rng) - 3);
    const Vector2 rb = RangeBearingSensor2(mount2).predict(robot, object.translation());
    const auto planar = CartesianGateFactor<SE2>::fromRangeBearing(poseKey(0), landmarkKey(0), rb,
                                                                  Vector2(0.1, 0.05).asDiagonal(), mount2);
    const auto spatial = CartesianGateFactor<SE3>::fromRangeBearingElevation(
        poseKey(0), landmarkKey(0), Vector3(rb(0), rb(1), 0.0), Vector3(0.1, 0.05, 0.02).asDiagonal(), level(mount2));
    const SE2 robotElsewhere(robot.x() + 0.4, robot.y() - 0.3, robot.theta() + 0.2);
    const SE2 objectElsewhere(object.x() - 0.2, object.y() + 0.5, object.theta());
    Values values2, values3;
    values2.insert(poseKey(0), robotElsewhere);
    values2.insert(landmarkKey(0), objectElsewhere);
    values3.insert(poseKey(0), level(robotElsewhere));
    values3.insert(landmarkKey(0), level(objectElsewhere));
    EXPECT_NEAR(spatial->chi2(values3), planar->chi2(values2), 1e-9 * (1.0 + planar->chi2(values2)));
  }
}
