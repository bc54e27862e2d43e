// The escape from the null basin (SemanticSlam step 7, docs/association-front-end.md §6b): a landmark's re-sightings
// that a drifting estimate has put beyond the null hypothesis's break-even are tried on it together, and kept there
// only where that lowers the max-mixture objective. The escape is for mixtures that the back end leaves on the
// null component they were linearized on; these runs use GTSAM's relinearization (every 10 updates, 0.1), under
// which the scenario below keeps them there, and the last test shows that paper B's default (every update, 0.05;
// slam/SemanticSlamSmoother.h) re-chooses them by itself.

#include <gtest/gtest.h>

#include <numbers>

#include "semslam/slam/SemanticSlam.h"
#include "semslam/solve/SmootherFactory.h"

namespace semslam {
namespace {

/// A robot that truly slips 0.15 m to its left at every 1 m step while its odometry reports a straight 1 m (the
/// slip lies within the declared σ of 0.1 m per step: the odometry is noisy, not wrong), watching one landmark
/// with a sharp relative-position sensor (σ 0.02 m, detections exact). From the second sighting on, the
/// prediction from the odometry is 7.5 detection σ or more off: past mm-nh's null break-even (about 4.8 σ in 2D),
/// though well inside the front end's gate, whose innovation covariance holds the pose's uncertainty.
struct SlippingRobot {
  LogHeader header;
  Point2 landmark{8.0, 1.0};

  SlippingRobot() {
    header.sensor.kind = SensorKind::RelativePosition;
    header.sensor.maxRange = 20.0;
    header.sensor.fieldOfView = std::numbers::pi;
    header.initialPose = PosePrior{SE2(), Vector3(1e-6, 1e-6, 1e-8).asDiagonal().toDenseMatrix()};
  }

  static SE2 truePose(int k) { return SE2(1.0 * k, 0.15 * k, 0.0); }

  TimeStep step(int k) const {
    TimeStep s;
    s.time = k;
    s.truePose = truePose(k);
    if (k > 0) s.odometry = Odometry{SE2(1.0, 0.0, 0.0), Vector3(0.01, 0.01, 1e-6).asDiagonal().toDenseMatrix()};
    Detection d;
    d.geometry = truePose(k).transformTo(landmark);
    d.covariance = 0.02 * 0.02 * Matrix::Identity(2, 2);
    d.truthId = 0;
    s.detections.push_back(d);
    return s;
  }
};

struct Outcome {
  int onLandmark = 0;  // detections whose final association is the landmark
  int onNull = 0;      // on no landmark
  double objective = 0.0;  // Σ chi2 of the graph at the final estimate: twice the max-mixture objective
};

Outcome run(bool nullEscape, int steps = 7, bool gtsamRelinearization = true) {
  const SlippingRobot robot;
  SemanticSlamOptions options;
  options.strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  options.birth = BirthRule::Unassigned;
  options.nullEscape = nullEscape;
  if (gtsamRelinearization) options.smoother = smootherFactory(SmootherKind::Incremental, {}, {});
  SemanticSlam slam(robot.header, options);
  for (int k = 0; k < steps; ++k) slam.addStep(robot.step(k));
  slam.finish();
  Outcome outcome;
  for (const DetectionRecord& record : slam.detections()) {
    const std::optional<int> chosen = slam.chosenAssociation(record).first;
    (chosen ? outcome.onLandmark : outcome.onNull) += 1;
  }
  outcome.objective = slam.smoother().factors().chi2(slam.smoother().estimate());
  return outcome;
}

TEST(NullEscape, PutsALandmarksResightingsBackWhereThatLowersTheObjective) {
  const Outcome without = run(false);
  // The scenario exercises the mechanism: without the escape, re-sightings sit on the null hypothesis.
  ASSERT_GE(without.onNull, 2);
  const Outcome with = run(true);
  EXPECT_EQ(with.onNull, 0);
  EXPECT_EQ(with.onLandmark, 7);
  // Each escape is accepted only where it lowers the objective, and here it does, by far.
  EXPECT_LT(with.objective, without.objective);
}

TEST(NullEscape, LeavesALoneNullDetectionToTheNullHypothesis) {
  // One re-sighting on null is what the null hypothesis is for (an outlier): the escape needs two of one landmark.
  const Outcome without = run(false, 2);
  ASSERT_EQ(without.onNull, 1);
  const Outcome with = run(true, 2);
  EXPECT_EQ(with.onNull, 1);
  EXPECT_DOUBLE_EQ(with.objective, without.objective);
}

TEST(NullEscape, IsNotNeededWhereTheBackEndRelinearizesAtEveryUpdate) {
  // Paper B's default back end relinearizes the slipping robot's poses at every update and re-chooses the mixtures
  // there: every re-sighting ends on the landmark without the escape, at the objective the escape reaches.
  const Outcome without = run(false, 7, false);
  EXPECT_EQ(without.onNull, 0);
  EXPECT_EQ(without.onLandmark, 7);
  EXPECT_NEAR(without.objective, run(true, 7, true).objective, 1e-6 * without.objective);
}

}  // namespace
}  // namespace semslam
