// Relative position sensors (2D and 3D): prediction with a body-to-sensor offset, back-projection, and the
// Jacobians against central differences on the manifold.

#include <gtest/gtest.h>

#include <functional>
#include <numbers>
#include <random>

#include "semslam/models/RelativePositionSensor2.h"
#include "semslam/models/RelativePositionSensor3.h"
#include "semslam/models/Sampling.h"
#include "support/NumericalDerivative.h"
#include "models/ModelsTesting.h"

namespace semslam {
namespace {

using test::matricesNear;
using test::numericalDerivative;

using test::randomSE3;
using test::uniform;

TEST(RelativePositionSensor2, PredictionWithSensorOffset) {
  // Robot at (1, 1) facing +y, sensor 0.5 m ahead along the body x axis: a point 2 m further ahead is at (2, 0).
  const RelativePositionSensor2 sensor(SE2(0.5, 0.0, 0.0));
  const SE2 robot(1.0, 1.0, std::numbers::pi / 2);
  EXPECT_TRUE(sensor.predict(robot, Point2(1.0, 3.5)).isApprox(Point2(2.0, 0.0), 1e-12));
  EXPECT_TRUE(sensor.predict(robot, Point2(0.0, 1.5)).isApprox(Point2(0.0, 1.0), 1e-12));  // to the left
  EXPECT_TRUE(sensor.backProject(robot, Point2(2.0, 0.0)).isApprox(Point2(1.0, 3.5), 1e-12));
  EXPECT_TRUE(RelativePositionSensor2::difference(Vector2(1.0, 2.0), Vector2(0.5, 3.0)).isApprox(Vector2(0.5, -1.0)));
}

TEST(RelativePositionSensor2, JacobiansMatchCentralDifferences) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 50; ++trial) {
    const RelativePositionSensor2 sensor(SE2(uniform(rng, -0.5, 0.5), uniform(rng, -0.2, 0.2), uniform(rng, -1, 1)));
    const SE2 robot(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -3.1, 3.1));
    const Point2 point(uniform(rng, -5, 5), uniform(rng, -5, 5));
    Matrix23 Hrobot;
    Matrix2 Hpoint;
    const Point2 p = sensor.predict(robot, point, &Hrobot, &Hpoint);
    EXPECT_TRUE(sensor.backProject(robot, p).isApprox(point, 1e-12));
    const std::function<Point2(const SE2&)> ofRobot = [&](const SE2& x) { return sensor.predict(x, point); };
    const std::function<Point2(const Point2&)> ofPoint = [&](const Point2& l) { return sensor.predict(robot, l); };
    EXPECT_TRUE(matricesNear(Hrobot, numericalDerivative(ofRobot, robot), 1e-8));
    EXPECT_TRUE(matricesNear(Hpoint, numericalDerivative(ofPoint, point), 1e-8));
  }
}

TEST(RelativePositionSensor3, PredictionWithSensorOffset) {
  // Sensor 0.3 m ahead and 0.2 m up, turned 90° about z: a point ahead of the robot appears on the sensor's −y axis.
  const RelativePositionSensor3 sensor(SE3(SO3::fromAxisAngle(Vector3::UnitZ(), std::numbers::pi / 2),
                                           Point3(0.3, 0.0, 0.2)));
  const SE3 robot;
  EXPECT_TRUE(sensor.predict(robot, Point3(2.3, 0.0, 0.2)).isApprox(Point3(0.0, -2.0, 0.0), 1e-12));
  EXPECT_TRUE(sensor.backProject(robot, Point3(0.0, -2.0, 0.0)).isApprox(Point3(2.3, 0.0, 0.2), 1e-12));
}

TEST(RelativePositionSensor3, JacobiansMatchCentralDifferences) {
  std::mt19937 rng(22);
  for (int trial = 0; trial < 50; ++trial) {
    const RelativePositionSensor3 sensor(randomSE3(rng, 0.5));
    const SE3 robot = randomSE3(rng, 5.0);
    const Point3 point(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
    Matrix36 Hrobot;
    Matrix3 Hpoint;
    const Point3 p = sensor.predict(robot, point, &Hrobot, &Hpoint);
    EXPECT_TRUE(sensor.backProject(robot, p).isApprox(point, 1e-12));
    const std::function<Point3(const SE3&)> ofRobot = [&](const SE3& x) { return sensor.predict(x, point); };
    const std::function<Point3(const Point3&)> ofPoint = [&](const Point3& l) { return sensor.predict(robot, l); };
    EXPECT_TRUE(matricesNear(Hrobot, numericalDerivative(ofRobot, robot), 1e-8));
    EXPECT_TRUE(matricesNear(Hpoint, numericalDerivative(ofPoint, point), 1e-8));
  }
}

}  // namespace
}  // namespace semslam
