// The visibility model: field-of-view and range edges in 2D (with a sensor offset) and 3D (a cone), and the object
// observation model P(β_k | x_k, X^o) (indicator and uniform-over-feasible forms; normalisation over all β).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "semslam/models/VisibilityModel.h"

namespace semslam {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEps = 1e-9;

Point2 polar(double range, double angle) { return Point2(range * std::cos(angle), range * std::sin(angle)); }

TEST(VisibilityModel2, FieldOfViewAndRangeEdges) {
  // 90° field of view, 10 m, the sensor 0.5 m ahead of the robot; the robot at (1, 2) facing +y.
  const SE2 robot(1.0, 2.0, kPi / 2);
  const VisibilityModel2 model(kPi / 2, 10.0, SE2(0.5, 0.0, 0.0));
  const SE2 sensor = robot * model.bodyToSensor();
  auto at = [&](double range, double angle) { return sensor.transformFrom(polar(range, angle)); };
  EXPECT_TRUE(model.visible(robot, at(5.0, 0.0)));
  EXPECT_TRUE(model.visible(robot, at(5.0, kPi / 4 - kEps)));
  EXPECT_FALSE(model.visible(robot, at(5.0, kPi / 4 + kEps)));
  EXPECT_TRUE(model.visible(robot, at(5.0, -kPi / 4 + kEps)));
  EXPECT_FALSE(model.visible(robot, at(5.0, -kPi / 4 - kEps)));
  EXPECT_TRUE(model.visible(robot, at(10.0 - kEps, 0.3)));
  EXPECT_FALSE(model.visible(robot, at(10.0 + kEps, 0.3)));
  EXPECT_FALSE(model.visible(robot, at(5.0, kPi)));  // behind
  // Range is measured from the sensor, not the robot: 10.2 m from the robot but 9.7 m from the sensor.
  EXPECT_TRUE(model.visible(robot, Point2(1.0, 12.2)));
  EXPECT_FALSE(model.visible(robot, sensor.translation()));  // at the sensor itself
  // Exactly on the edges (exactly representable): inclusive.
  const VisibilityModel2 atOrigin(kPi / 2, 10.0);
  EXPECT_TRUE(atOrigin.visible(SE2(), Point2(10.0, 0.0)));
  EXPECT_TRUE(atOrigin.visible(SE2(), Point2(3.0, 3.0)));
  EXPECT_TRUE(atOrigin.visible(SE2(), Point2(3.0, -3.0)));
}

TEST(VisibilityModel2, ZeroMeansUnlimited) {
  const VisibilityModel2 all;  // fieldOfView 0: all around; maxRange 0: unlimited
  EXPECT_TRUE(all.visible(SE2(), Point2(-1e6, 1.0)));
  EXPECT_TRUE(all.visible(SE2(0.0, 0.0, 1.0), polar(3.0, kPi)));
  const VisibilityModel2 wide(2 * kPi, 5.0);
  EXPECT_TRUE(wide.visible(SE2(), Point2(-4.0, 0.0)));
  EXPECT_FALSE(wide.visible(SE2(), Point2(-6.0, 0.0)));
  const VisibilityModel2 fovOnly(1.0, 0.0);
  EXPECT_TRUE(fovOnly.visible(SE2(), Point2(1e9, 0.0)));
  EXPECT_THROW(VisibilityModel2(-0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(VisibilityModel2(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(VisibilityModel2(std::nan(""), 1.0), std::invalid_argument);

  SensorSpec spec;
  spec.fieldOfView = 1.0;
  spec.maxRange = 4.0;
  spec.bodyToSensor = SE2(0.2, 0.0, 0.0);
  const VisibilityModel2 fromSpec = VisibilityModel2::fromSpec(spec);
  EXPECT_EQ(fromSpec.fieldOfView(), 1.0);
  EXPECT_EQ(fromSpec.maxRange(), 4.0);
  EXPECT_TRUE(fromSpec.bodyToSensor().equals(SE2(0.2, 0.0, 0.0), 0.0));
  EXPECT_THROW(VisibilityModel3::fromSpec(spec), std::invalid_argument);
}

TEST(VisibilityModel3, ConeAndRangeEdges) {
  // A 60° cone about the sensor's x axis, 8 m; the sensor turned to look along the robot's +y axis.
  const VisibilityModel3 model(kPi / 3, 8.0, SE3(SO3::fromAxisAngle(Vector3::UnitZ(), kPi / 2), Point3::Zero()));
  const SE3 robot(SO3(), Point3(1.0, 1.0, 1.0));
  const SE3 sensor = robot * model.bodyToSensor();
  // A direction at angle a off the sensor's x axis, rotated by ψ about it.
  auto at = [&](double range, double a, double psi) {
    return sensor.transformFrom(range * Point3(std::cos(a), std::sin(a) * std::cos(psi), std::sin(a) * std::sin(psi)));
  };
  for (const double psi : {0.0, 0.7, kPi / 2, 2.5, -1.0}) {
    EXPECT_TRUE(model.visible(robot, at(4.0, kPi / 6 - kEps, psi))) << psi;
    EXPECT_FALSE(model.visible(robot, at(4.0, kPi / 6 + kEps, psi))) << psi;
  }
  EXPECT_TRUE(model.visible(robot, at(8.0 - kEps, 0.1, 0.3)));
  EXPECT_FALSE(model.visible(robot, at(8.0 + kEps, 0.1, 0.3)));
  EXPECT_FALSE(model.visible(robot, at(3.0, kPi, 0.0)));
  EXPECT_TRUE(model.visible(robot, Point3(1.0, 5.0, 1.0)));    // along the robot's +y: the sensor's axis
  EXPECT_FALSE(model.visible(robot, Point3(5.0, 1.0, 1.0)));   // along the robot's +x: 90° off it
  // A wide cone (more than a half space).
  const VisibilityModel3 wide(1.5 * kPi, 0.0);
  EXPECT_TRUE(wide.visible(SE3(), Point3(-1.0, 1.01, 0.0)));   // 134.7° off axis < 135°
  EXPECT_FALSE(wide.visible(SE3(), Point3(-1.0, 0.99, 0.0)));  // 135.3°
}

TEST(VisibilityModel2, AssociationProbabilityFollowsTheVisibleObjects) {
  // Objects 0, 1, 3 in view; 2 behind; 4 too far.
  const VisibilityModel2 model(kPi / 2, 10.0);
  const std::vector<Point2> objects = {Point2(2.0, 0.5), Point2(5.0, -1.0), Point2(-3.0, 0.0), Point2(7.0, 2.0),
                                       Point2(20.0, 0.0)};
  const SE2 robot;
  EXPECT_EQ(model.visibleObjects(robot, objects), (std::vector<int>{0, 1, 3}));
  const std::vector<int> good = {3, 0}, hidden = {0, 2}, twice = {1, 1}, none = {};
  EXPECT_TRUE(model.associationFeasible(robot, objects, good));
  EXPECT_FALSE(model.associationFeasible(robot, objects, hidden));
  EXPECT_FALSE(model.associationFeasible(robot, objects, twice));
  // Uniform over the 3·2 ordered assignments of 2 detections to 3 visible objects.
  EXPECT_DOUBLE_EQ(model.associationProbability(robot, objects, good), 1.0 / 6.0);
  EXPECT_EQ(model.associationProbability(robot, objects, hidden), 0.0);
  EXPECT_EQ(model.associationProbability(robot, objects, twice), 0.0);
  EXPECT_EQ(model.associationProbability(robot, objects, none), 1.0);
  const std::vector<int> four = {0, 1, 3, 0};
  EXPECT_EQ(model.associationProbability(robot, objects, four), 0.0);
  const std::vector<int> outside = {5};
  EXPECT_THROW(model.associationProbability(robot, objects, outside), std::invalid_argument);

  // Summed over every β ∈ [0, N)^n, the probabilities are one (n = 1, 2, 3), with and without exclusivity.
  const VisibilityModel2 shared(kPi / 2, 10.0, SE2(), false);
  for (int n = 1; n <= 3; ++n) {
    double total = 0.0, totalShared = 0.0;
    int count = 1;
    for (int i = 0; i < n; ++i) count *= 5;
    for (int code = 0; code < count; ++code) {
      std::vector<int> beta;
      for (int i = 0, rest = code; i < n; ++i, rest /= 5) beta.push_back(rest % 5);
      total += model.associationProbability(robot, objects, beta);
      totalShared += shared.associationProbability(robot, objects, beta);
    }
    EXPECT_NEAR(total, 1.0, 1e-12) << n;
    EXPECT_NEAR(totalShared, 1.0, 1e-12) << n;
  }
  EXPECT_DOUBLE_EQ(shared.associationProbability(robot, objects, twice), 1.0 / 9.0);
  EXPECT_EQ(model.uniformAssociationProbability(0, 1), 0.0);
  EXPECT_NEAR(model.uniformAssociationProbability(100, 5), 1.0 / (100.0 * 99 * 98 * 97 * 96), 1e-22);
}

TEST(VisibilityModel2, TheIndicatorIsTheProductOfEachAssociatedObjectsVisibility) {
  // hybrid/PropWeights.cpp adds per-object log visibilities: for distinct objects the indicator factors.
  const VisibilityModel2 model(std::numbers::pi / 2.0, 6.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-6.0, 6.0), angle(-std::numbers::pi, std::numbers::pi);
  int feasible = 0, infeasible = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const SE2 robot(0.25 * coordinate(rng), 0.25 * coordinate(rng), angle(rng));
    std::vector<Point2> objects;
    for (int i = 0; i < 4; ++i) objects.emplace_back(coordinate(rng), coordinate(rng));
    const std::vector<int> beta{trial % 4, (trial / 4) % 4 == trial % 4 ? (trial + 1) % 4 : (trial / 4) % 4};
    const bool product = model.visible(robot, objects[beta[0]]) && model.visible(robot, objects[beta[1]]);
    EXPECT_EQ(model.associationFeasible(robot, objects, beta), product);
    (product ? feasible : infeasible) += 1;
  }
  EXPECT_GT(feasible, 30);  // both outcomes were exercised
  EXPECT_GT(infeasible, 100);
}

TEST(VisibilityModel3, AssociationProbability) {
  const VisibilityModel3 model(kPi / 2, 10.0);
  const std::vector<Point3> objects = {Point3(3.0, 0.0, 0.5), Point3(4.0, 1.0, -1.0), Point3(0.0, 0.0, 5.0)};
  const std::vector<int> both = {1, 0}, up = {2};
  EXPECT_EQ(model.visibleObjects(SE3(), objects), (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(model.associationProbability(SE3(), objects, both), 0.5);
  EXPECT_FALSE(model.associationFeasible(SE3(), objects, up));
}

}  // namespace
}  // namespace semslam
