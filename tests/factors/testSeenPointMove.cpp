// How far a landmark seen from the robot can have moved (factors/SeenPointMove.h), and the detection factors' bounds
// on how far their whitened error moves with it (Factor::whitenedErrorBoundForSeenMove): never below the true
// change, exact where the header says so, and absent where they cannot hold (a bearing near its ±π seam, a point
// that may pass the sensor, a robust kernel).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "semslam/factors/RangeBearingElevationFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/factors/SeenPointMove.h"
#include "semslam/graph/NoiseModel.h"

using namespace semslam;

namespace {

std::mt19937 rng(11);
double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
/// A size between 1e-5 and 1 spread evenly in its logarithm: the bounds are used for small moves, tested on all.
double logUniform() { return std::pow(10.0, uniform(-5.0, 0.0)); }

Vector3 randomVector3(double scale) { return scale * Vector3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)); }
SE2 randomSE2() { return SE2(uniform(-5, 5), uniform(-5, 5), uniform(-3.1, 3.1)); }
SE3 randomSE3() {
  return SE3(SO3::fromAxisAngle(randomVector3(1.0).normalized(), uniform(-3.1, 3.1)), Point3(randomVector3(5.0)));
}

/// A random covariance with correlation: the bounds must hold for full square-root information matrices.
Matrix randomCovariance(int dimension, const Vector& sigmas) {
  Matrix a = Matrix::Identity(dimension, dimension);
  for (int i = 0; i < dimension; ++i) {
    for (int j = 0; j < dimension; ++j) a(i, j) += uniform(-0.5, 0.5);
  }
  Matrix c = a * a.transpose();
  const Vector scale = sigmas.array() / c.diagonal().array().sqrt();
  return scale.asDiagonal() * c * scale.asDiagonal();
}

Vector whitenedError(const Factor& factor, const Values& values) {
  LinearizedFactor out;
  factor.linearize(values, out);
  return out.whitenedError;
}

const Key kPose = poseKey(0);
const Key kLandmark = landmarkKey(0);

}  // namespace

TEST(SeenPointMove, BoundsHowFarTheLandmarkSeenFromTheRobotMovedInThePlaneAndInSpace) {
  for (int trial = 0; trial < 2000; ++trial) {
    const SE2 from = randomSE2();
    const Point2 point(uniform(-8, 8), uniform(-8, 8));
    const SE2 to = from.retract(randomVector3(logUniform()));
    const Point2 pointTo = point + Point2(uniform(-1, 1), uniform(-1, 1)) * logUniform();
    const double bound = seenPointMove(from, point, to, pointTo);
    const double moved = (to.transformTo(pointTo) - from.transformTo(point)).norm();
    EXPECT_LE(moved, bound * (1.0 + 1e-12) + 1e-15) << "trial " << trial;
    EXPECT_EQ(seenPointMove(Value(from), Value(point), Value(to), Value(pointTo)), bound);
  }
  for (int trial = 0; trial < 2000; ++trial) {
    const SE3 from = randomSE3();
    const Point3 point(randomVector3(8.0));
    Vector6 delta;
    delta << randomVector3(logUniform()), randomVector3(logUniform());
    const SE3 to = from.retract(delta);
    const Point3 pointTo = point + randomVector3(logUniform());
    const double bound = seenPointMove(from, point, to, pointTo);
    const double moved = (to.transformTo(pointTo) - from.transformTo(point)).norm();
    EXPECT_LE(moved, bound * (1.0 + 1e-12) + 1e-15) << "trial " << trial;
    EXPECT_EQ(seenPointMove(Value(from), Value(point), Value(to), Value(pointTo)), bound);
  }
}

TEST(SeenPointMove, IsExactForAMovedPointAndForATurnAboutTheRobotsOrigin) {
  // The point alone moves: p moves by exactly ‖Δl‖.
  const SE2 robot(1.0, 2.0, 0.3);
  EXPECT_NEAR(seenPointMove(robot, Point2(4.0, 6.0), robot, Point2(4.0, 6.5)), 0.5, 1e-15);
  // The robot turns by φ about its origin: p moves along a chord of length 2 ρ sin(φ/2), which is ε exactly
  // (‖R − R₀‖₂ = ‖R − R₀‖_F / √2; without the √2 the bound would be √2 too large, with a wrong factor too small).
  for (double phi : {1e-4, 0.1, 1.0, 3.0}) {
    const SE2 turned(1.0, 2.0, 0.3 + phi);
    const double bound = seenPointMove(robot, Point2(4.0, 6.0), turned, Point2(4.0, 6.0));
    EXPECT_NEAR(bound, 2.0 * 5.0 * std::sin(phi / 2.0), 1e-12) << "phi " << phi;
    EXPECT_NEAR((turned.transformTo(Point2(4.0, 6.0)) - robot.transformTo(Point2(4.0, 6.0))).norm(), bound, 1e-12);
    const SE3 robot3(SO3::fromAxisAngle(Vector3(0.0, 0.0, 1.0), 0.3), Point3(1.0, 2.0, 0.0));
    const SE3 turned3(SO3::fromAxisAngle(Vector3(0.0, 0.0, 1.0), 0.3 + phi), Point3(1.0, 2.0, 0.0));
    EXPECT_NEAR(seenPointMove(robot3, Point3(4.0, 6.0, 0.0), turned3, Point3(4.0, 6.0, 0.0)),
                2.0 * 5.0 * std::sin(phi / 2.0), 1e-12)
        << "phi " << phi;
  }
}

TEST(SeenPointMove, ReadsAnObjectsPositionAndRefusesValuesThatAreNoRobotAndLandmark) {
  const SE2 robot(1.0, 2.0, 0.3);
  const SE2 object(4.0, 6.0, 1.0);
  const SE2 turnedObject(4.0, 6.5, -2.0);  // its orientation does not matter, its position moved by 0.5
  EXPECT_NEAR(*seenPointMove(Value(robot), Value(object), Value(robot), Value(turnedObject)), 0.5, 1e-15);
  EXPECT_FALSE(seenPointMove(Value(robot), Value(Point3(1, 2, 3)), Value(robot), Value(Point3(1, 2, 3))));
  EXPECT_FALSE(seenPointMove(Value(Point2(0, 0)), Value(Point2(1, 1)), Value(Point2(0, 0)), Value(Point2(1, 1))));
  EXPECT_FALSE(seenPointMove(Value(robot), Value(Point2(1, 1)), Value(SE3()), Value(Point2(1, 1))));
}

/// Moves of size below 1e-2, and how many of them the factor bounded.
struct BoundTally {
  int small = 0;
  int bounded = 0;
};

/// The factor's bound for the move from `from` to `to` (a move of `size`), where it gives one, is at least the true
/// change of its whitened error.
void expectBoundHolds(const Factor& factor, const Values& from, const Values& to, double size, BoundTally& tally) {
  const std::optional<double> bound = factor.whitenedErrorBoundForSeenMove(
      from, factor.chi2(from),
      *seenPointMove(from.value(kPose), from.value(kLandmark), to.value(kPose), to.value(kLandmark)));
  if (size < 1e-2) ++tally.small;
  if (!bound) return;
  if (size < 1e-2) ++tally.bounded;
  const double change = (whitenedError(factor, to) - whitenedError(factor, from)).norm();
  EXPECT_LE(change, *bound * (1.0 + 1e-9) + 1e-12) << "move of size " << size;
}

template <class Landmark>
void expectRangeBearingBoundHolds() {
  BoundTally tally;
  for (int trial = 0; trial < 3000; ++trial) {
    const SE2 offset(uniform(-0.5, 0.5), uniform(-0.2, 0.2), uniform(-0.3, 0.3));
    const RangeBearingSensor2 sensor(offset);
    Values from;
    from.insert(kPose, randomSE2());
    Landmark landmark;
    if constexpr (std::is_same_v<Landmark, Point2>) {
      landmark = Point2(uniform(-10, 10), uniform(-10, 10));
    } else {
      landmark = randomSE2();
    }
    from.insert(kLandmark, landmark);
    const Point2 position = LandmarkPosition<Landmark>::of(landmark, nullptr);
    if ((from.at<SE2>(kPose) * offset).transformTo(position).norm() < 0.5) continue;
    // The measurement: the prediction with an error of up to a few σ.
    const Vector2 sigmas(uniform(0.02, 0.3), uniform(0.005, 0.1));
    const Vector2 z =
        sensor.predict(from.at<SE2>(kPose), position) + Vector2(sigmas(0) * uniform(-4, 4), sigmas(1) * uniform(-4, 4));
    const RangeBearingFactor<Landmark> factor(kPose, kLandmark, z,
                                              NoiseModel::fromCovariance(randomCovariance(2, sigmas)), sensor);
    const double size = logUniform();
    Values to;
    to.insert(kPose, from.at<SE2>(kPose).retract(randomVector3(size)));
    Vector delta(Manifold<Landmark>::kDim);
    for (int i = 0; i < delta.size(); ++i) delta(i) = uniform(-size, size);
    to.insert(kLandmark, Manifold<Landmark>::retract(landmark, delta));
    expectBoundHolds(factor, from, to, size, tally);
  }
  EXPECT_EQ(tally.bounded, tally.small);  // every small move is bounded (none comes near the seam or the sensor here)
  EXPECT_GT(tally.small, 500);
}

TEST(RangeBearingFactor, WhitenedErrorChangeBoundHoldsForPointsAndObjectPoses) {
  expectRangeBearingBoundHolds<Point2>();
  expectRangeBearingBoundHolds<SE2>();
}

TEST(RangeBearingFactor, NoWhitenedErrorChangeBoundNearTheBearingsSeamOrPastTheSensor) {
  const SharedNoiseModel noise = NoiseModel::fromSigmas(Vector2(0.1, 0.5));
  Values from;
  from.insert(kPose, SE2(0.0, 0.0, 0.0));
  from.insert(kLandmark, Point2(4.0, 0.0));
  // Bearing error π − 0.01 at `from`: a turn of 0.02 rad takes it across the seam, to −π + 0.01, a jump of
  // 2π − 0.02 in the error. No bound may be given there.
  const RangeBearingFactor<Point2> seam(kPose, kLandmark, Vector2(4.0, std::numbers::pi - 0.01), noise);
  Values turned = from;
  turned.update(kPose, SE2(0.0, 0.0, 0.02));
  const double jump = (whitenedError(seam, turned) - whitenedError(seam, from)).norm();
  EXPECT_GT(jump, 2.0 * std::numbers::pi);  // the case is what it claims to be
  const double turn =
      *seenPointMove(from.value(kPose), from.value(kLandmark), turned.value(kPose), turned.value(kLandmark));
  EXPECT_FALSE(seam.whitenedErrorBoundForSeenMove(from, seam.chi2(from), turn));
  // Far from the seam the same turn is bounded.
  const RangeBearingFactor<Point2> inlier(kPose, kLandmark, Vector2(4.0, 0.1), noise);
  EXPECT_TRUE(inlier.whitenedErrorBoundForSeenMove(from, inlier.chi2(from), turn));
  // A move as large as the point's distance from the sensor: its bearing could be anything.
  EXPECT_FALSE(inlier.whitenedErrorBoundForSeenMove(from, inlier.chi2(from), 4.0));
  EXPECT_TRUE(inlier.whitenedErrorBoundForSeenMove(from, inlier.chi2(from), 1.0));
  // Under a robust kernel the whitened error is not the factor's cost: no bound.
  const RangeBearingFactor<Point2> robust(kPose, kLandmark, Vector2(4.0, 0.1),
                                          noise->withRobustKernel(std::make_shared<CauchyKernel>(1.0)));
  EXPECT_FALSE(robust.whitenedErrorBoundForSeenMove(from, robust.chi2(from), turn));
}

template <class Landmark>
void expectRangeBearingElevationBoundHolds() {
  BoundTally tally;
  for (int trial = 0; trial < 3000; ++trial) {
    const RangeBearingElevationSensor3 sensor(
        SE3(SO3::fromAxisAngle(randomVector3(1.0).normalized(), uniform(-0.3, 0.3)), Point3(randomVector3(0.3))));
    Values from;
    from.insert(kPose, randomSE3());
    Landmark landmark;
    if constexpr (std::is_same_v<Landmark, Point3>) {
      landmark = Point3(randomVector3(10.0));
    } else {
      landmark = randomSE3();
    }
    from.insert(kLandmark, landmark);
    const Point3 position = LandmarkPosition<Landmark>::of(landmark, nullptr);
    const Point3 seen = (from.at<SE3>(kPose) * sensor.bodyToSensor()).transformTo(position);
    if (seen.head<2>().norm() < 0.5) continue;  // near the sensor's z axis the bearing is undefined
    const Vector3 sigmas(uniform(0.02, 0.3), uniform(0.005, 0.1), uniform(0.005, 0.1));
    const Vector3 z = sensor.predict(from.at<SE3>(kPose), position) +
                      Vector3(sigmas(0) * uniform(-4, 4), sigmas(1) * uniform(-4, 4), sigmas(2) * uniform(-4, 4));
    const RangeBearingElevationFactor<Landmark> factor(kPose, kLandmark, z,
                                                       NoiseModel::fromCovariance(randomCovariance(3, sigmas)), sensor);
    const double size = logUniform();
    Vector6 poseDelta;
    poseDelta << randomVector3(size), randomVector3(size);
    Vector delta(Manifold<Landmark>::kDim);
    for (int i = 0; i < delta.size(); ++i) delta(i) = uniform(-size, size);
    Values to;
    to.insert(kPose, from.at<SE3>(kPose).retract(poseDelta));
    to.insert(kLandmark, Manifold<Landmark>::retract(landmark, delta));
    expectBoundHolds(factor, from, to, size, tally);
  }
  // Small moves are bounded but for a few of the random covariances so ill-conditioned that ‖r‖ √Σ_ii, the
  // seam test's bound on an angle's error, exceeds π (chi2 of 1e4-1e6 for errors of a few σ).
  EXPECT_GE(tally.bounded, 0.99 * tally.small);
  EXPECT_GT(tally.small, 500);
}

TEST(RangeBearingElevationFactor, WhitenedErrorChangeBoundHoldsForPointsAndObjectPoses) {
  expectRangeBearingElevationBoundHolds<Point3>();
  expectRangeBearingElevationBoundHolds<SE3>();
}

TEST(RangeBearingElevationFactor, NoWhitenedErrorChangeBoundNearTheSensorsAxisOrTheBearingsSeam) {
  const SharedNoiseModel noise = NoiseModel::fromSigmas(Vector3(0.1, 0.5, 0.5));
  Values from;
  from.insert(kPose, SE3());
  from.insert(kLandmark, Point3(1.0, 0.0, 5.0));  // 1 m off the sensor's z axis, 5.1 m away
  const RangeBearingElevationFactor<Point3> inlier(kPose, kLandmark, Vector3(5.1, 0.0, 1.37), noise);
  EXPECT_TRUE(inlier.whitenedErrorBoundForSeenMove(from, inlier.chi2(from), 0.5));
  EXPECT_FALSE(inlier.whitenedErrorBoundForSeenMove(from, inlier.chi2(from), 1.0));  // could pass the axis
  const RangeBearingElevationFactor<Point3> seam(kPose, kLandmark, Vector3(5.1, std::numbers::pi - 0.01, 1.37), noise);
  EXPECT_FALSE(seam.whitenedErrorBoundForSeenMove(from, seam.chi2(from), 0.05));
}

TEST(RelativePointFactor, WhitenedErrorChangeBoundHoldsInThePlaneAndInSpace) {
  for (int trial = 0; trial < 2000; ++trial) {
    const double size = logUniform();
    Values from, to;
    from.insert(kPose, randomSE2());
    from.insert(kLandmark, Point2(uniform(-10, 10), uniform(-10, 10)));
    to.insert(kPose, from.at<SE2>(kPose).retract(randomVector3(size)));
    to.insert(kLandmark, Point2(from.at<Point2>(kLandmark) + Point2(uniform(-size, size), uniform(-size, size))));
    const RelativePointFactor<SE2, Point2> factor(kPose, kLandmark, Point2(uniform(-5, 5), uniform(-5, 5)),
                                                  NoiseModel::fromCovariance(randomCovariance(2, Vector2(0.1, 0.3))));
    const std::optional<double> bound = factor.whitenedErrorBoundForSeenMove(
        from, factor.chi2(from),
        *seenPointMove(from.value(kPose), from.value(kLandmark), to.value(kPose), to.value(kLandmark)));
    ASSERT_TRUE(bound);
    EXPECT_LE((whitenedError(factor, to) - whitenedError(factor, from)).norm(), *bound * (1.0 + 1e-9) + 1e-12);
  }
  for (int trial = 0; trial < 2000; ++trial) {
    const double size = logUniform();
    Values from, to;
    from.insert(kPose, randomSE3());
    from.insert(kLandmark, Point3(randomVector3(10.0)));
    Vector6 delta;
    delta << randomVector3(size), randomVector3(size);
    to.insert(kPose, from.at<SE3>(kPose).retract(delta));
    to.insert(kLandmark, Point3(from.at<Point3>(kLandmark) + randomVector3(size)));
    const RelativePointFactor<SE3, Point3> factor(
        kPose, kLandmark, Point3(randomVector3(5.0)),
        NoiseModel::fromCovariance(randomCovariance(3, Vector3(0.1, 0.2, 0.4))));
    const std::optional<double> bound = factor.whitenedErrorBoundForSeenMove(
        from, factor.chi2(from),
        *seenPointMove(from.value(kPose), from.value(kLandmark), to.value(kPose), to.value(kLandmark)));
    ASSERT_TRUE(bound);
    EXPECT_LE((whitenedError(factor, to) - whitenedError(factor, from)).norm(), *bound * (1.0 + 1e-9) + 1e-12);
  }
}
