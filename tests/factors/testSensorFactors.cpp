// Range-bearing (2D) and range-bearing-elevation (3D) factors, to points and to object poses, with sensor offsets.

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "semslam/factors/RangeBearingElevationFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/factors/RelativePoseFactor.h"
#include "support/FactorTesting.h"

using namespace semslam;
using semslam::test::expectJacobiansMatch;

namespace {

std::mt19937 rng(7);
double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

SE3 randomSE3(double translation = 5.0) {
  const Vector3 axis = Vector3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
  return SE3(SO3::fromAxisAngle(axis, uniform(-3.1, 3.1)),
             Point3(uniform(-translation, translation), uniform(-translation, translation),
                    uniform(-translation, translation)));
}

}  // namespace

TEST(RangeBearingFactor, PredictionWithSensorOffset) {
  // Robot at the origin facing +y, sensor 0.5 m ahead of it: a point 2 m further ahead is at range 2, bearing 0.
  const RangeBearingSensor2 sensor(SE2(0.5, 0.0, 0.0));
  const SE2 robot(0.0, 0.0, std::numbers::pi / 2);
  const Vector2 h = sensor.predict(robot, Point2(0.0, 2.5));
  EXPECT_NEAR(h(0), 2.0, 1e-12);
  EXPECT_NEAR(h(1), 0.0, 1e-12);
  const Vector2 left = sensor.predict(robot, Point2(-1.0, 0.5));
  EXPECT_NEAR(left(0), 1.0, 1e-12);
  EXPECT_NEAR(left(1), std::numbers::pi / 2, 1e-12);
  EXPECT_TRUE(sensor.backProject(robot, h).isApprox(Point2(0.0, 2.5), 1e-12));
}

TEST(RangeBearingFactor, BearingErrorIsWrappedAcrossThePiSeam) {
  const Vector2 e = RangeBearingSensor2::difference(Vector2(1.0, std::numbers::pi - 0.01),
                                                    Vector2(1.0, -std::numbers::pi + 0.01));
  EXPECT_NEAR(e(1), -0.02, 1e-12);
}

TEST(RangeBearingFactor, JacobiansToPointsAndObjectPoses) {
  for (int trial = 0; trial < 40; ++trial) {
    Values values;
    const SE2 robot(uniform(-5, 5), uniform(-5, 5), uniform(-3.14, 3.14));
    const Point2 point(uniform(-5, 5), uniform(-5, 5));
    values.insert(poseKey(0), robot);
    values.insert(landmarkKey(0), point);
    values.insert(Symbol('o', 0), SE2(point.x(), point.y(), uniform(-3, 3)));
    const RangeBearingSensor2 sensor(SE2(uniform(-0.5, 0.5), uniform(-0.2, 0.2), uniform(-0.3, 0.3)));
    // Measurements whose bearing sits near ±π relative to the prediction exercise the wrap.
    const Vector2 measured = sensor.predict(robot, point) + Vector2(0.1, trial % 3 == 0 ? 3.1 : 0.05);
    auto noise = NoiseModel::fromSigmas(Vector2(0.1, 0.05));
    expectJacobiansMatch(RangeBearingFactor<Point2>(poseKey(0), landmarkKey(0), measured, noise, sensor), values);
    expectJacobiansMatch(RangeBearingFactor<SE2>(poseKey(0), Symbol('o', 0), measured, noise, sensor), values);
  }
}

TEST(RangeBearingElevationFactor, PredictionAndBackProjection) {
  const RangeBearingElevationSensor3 sensor;
  const Vector3 h = sensor.predict(SE3(), Point3(1.0, 1.0, std::sqrt(2.0)));
  EXPECT_NEAR(h(0), 2.0, 1e-12);
  EXPECT_NEAR(h(1), std::numbers::pi / 4, 1e-12);
  EXPECT_NEAR(h(2), std::numbers::pi / 4, 1e-12);
  const SE3 robot = randomSE3();
  const RangeBearingElevationSensor3 mounted(randomSE3(0.5));
  const Point3 point(3.0, -2.0, 1.0);
  EXPECT_TRUE(mounted.backProject(robot, mounted.predict(robot, point)).isApprox(point, 1e-12));
}

TEST(RangeBearingElevationFactor, JacobiansToPointsAndObjectPoses) {
  for (int trial = 0; trial < 40; ++trial) {
    Values values;
    const SE3 robot = randomSE3();
    const Point3 point(uniform(-5, 5), uniform(-5, 5), uniform(-5, 5));
    values.insert(poseKey(0), robot);
    values.insert(landmarkKey(0), point);
    values.insert(Symbol('o', 0), SE3(randomSE3().rotation(), point));
    const RangeBearingElevationSensor3 sensor(randomSE3(0.3));
    const Vector3 measured = sensor.predict(robot, point) + Vector3(0.1, 0.05, -0.05);
    auto noise = NoiseModel::fromSigmas(Vector3(0.1, 0.05, 0.05));
    expectJacobiansMatch(RangeBearingElevationFactor<Point3>(poseKey(0), landmarkKey(0), measured, noise, sensor),
                         values);
    expectJacobiansMatch(RangeBearingElevationFactor<SE3>(poseKey(0), Symbol('o', 0), measured, noise, sensor),
                         values);
  }
}

TEST(RelativePoseFactor, ErrorIsTheObjectPoseSeenFromTheRobot) {
  const SE2 robot(1.0, 2.0, 0.5), object(3.0, 1.0, -1.0);
  Values values;
  values.insert(poseKey(0), robot);
  values.insert(Symbol('o', 1), object);
  const RelativePoseFactor<SE2> factor(poseKey(0), Symbol('o', 1), robot.between(object),
                                       NoiseModel::isotropic(3, 0.1));
  EXPECT_LE(factor.unwhitenedError(values).norm(), 1e-12);
  expectJacobiansMatch(factor, values);
}
