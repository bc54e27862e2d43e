// The aliased2d simulator: determinism, valid logs, the noise statistics against the stated covariances,
// detections only inside the field of view and range, the track-sampling policy, and the aliasing property of
// the default layout (geometry alone cannot tell the bays apart; the viewpoint-dependent classifier can).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "SimTesting.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/models/AnalyticViewpointClassifier.h"
#include "semslam/models/Angle.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/Viewpoint.h"
#include "semslam/models/VisibilityModel.h"
#include "semslam/sim/Aliased2dSimulator.h"

namespace semslam {
namespace {

using test::MomentCheck;
using test::ScratchFolder;

constexpr double kPi = std::numbers::pi;

SE2 truePose(const TimeStep& step) { return std::get<SE2>(*step.truePose); }

const Aliased2dObject& objectById(const Aliased2dScenario& scenario, int id) {
  for (const Aliased2dObject& object : scenario.objects) {
    if (object.id == id) return object;
  }
  throw std::out_of_range("no object " + std::to_string(id));
}

TEST(Aliased2d, SameSeedSameBytesDifferentSeedDifferentBytes) {
  ScratchFolder folder;
  const Aliased2dScenario scenario = defaultAliased2dScenario();
  const std::string a = test::logBytes(simulateAliased2dTrack(scenario, 7, 0, 25), folder, "a.jsonl");
  const std::string b = test::logBytes(simulateAliased2dTrack(scenario, 7, 0, 25), folder, "b.jsonl");
  const std::string c = test::logBytes(simulateAliased2dTrack(scenario, 8, 0, 25), folder, "c.jsonl");
  const std::string d = test::logBytes(simulateAliased2dTrack(scenario, 7, 1, 25), folder, "d.jsonl");
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(a, d);  // another track of the same run
}

TEST(Aliased2d, ChangingAlphaChangesOnlyTheScores) {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  const MeasurementLog a = simulateAliased2dTrack(scenario, 3, 2, 20);
  scenario.alpha = 0.5;
  const MeasurementLog b = simulateAliased2dTrack(scenario, 3, 2, 20);
  ASSERT_EQ(a.steps.size(), b.steps.size());
  bool scoresDiffer = false;
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    EXPECT_TRUE(truePose(a.steps[k]).equals(truePose(b.steps[k]), 0.0));
    ASSERT_EQ(a.steps[k].detections.size(), b.steps[k].detections.size());
    for (std::size_t i = 0; i < a.steps[k].detections.size(); ++i) {
      EXPECT_EQ(a.steps[k].detections[i].geometry, b.steps[k].detections[i].geometry);
      EXPECT_EQ(a.steps[k].detections[i].truthId, b.steps[k].detections[i].truthId);
      scoresDiffer |= *a.steps[k].detections[i].classVector != *b.steps[k].detections[i].classVector;
    }
  }
  EXPECT_TRUE(scoresDiffer);
  EXPECT_EQ(std::get<SE2>(a.header.initialPose->mean).x(), std::get<SE2>(b.header.initialPose->mean).x());
}

TEST(Aliased2d, GeneratedLogsReadBackAndDescribeTheScenario) {
  ScratchFolder folder;
  const Aliased2dScenario scenario = defaultAliased2dScenario();
  for (int track = 0; track < 5; ++track) {
    const std::string path = folder.file("t" + std::to_string(track) + ".jsonl");
    writeMeasurementLog(path, simulateAliased2dTrack(scenario, 11, track, 30, 5));
    const MeasurementLog log = readMeasurementLog(path);
    const LogHeader& h = log.header;
    EXPECT_EQ(h.dimension, 2);
    EXPECT_EQ(h.classes, 2);
    EXPECT_EQ(h.semantic, SemanticKind::Scores);
    EXPECT_EQ(h.classifier.kind, ClassifierModelSpec::Kind::ViewpointGaussian);
    EXPECT_EQ(h.classifier.alpha, 0.25);
    EXPECT_EQ(h.classifier.sharpness, 15.0);
    EXPECT_EQ(h.sensor.kind, SensorKind::RangeBearing);
    EXPECT_EQ(h.sensor.maxRange, scenario.sensor.maxRange);
    EXPECT_EQ(h.sensor.fieldOfView, scenario.sensor.fieldOfView);
    EXPECT_TRUE(h.landmarksHavePose);
    ASSERT_TRUE(h.initialPose);
    EXPECT_EQ(h.initialPose->covariance, Matrix(scenario.priors.initialPoseCovariance));
    ASSERT_EQ(h.landmarkPriors.size(), 6u);
    ASSERT_EQ(h.landmarkTruth.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
      EXPECT_EQ(h.landmarkTruth[i].id, scenario.objects[i].id);
      EXPECT_EQ(h.landmarkTruth[i].classIndex, scenario.objects[i].classIndex);
      EXPECT_TRUE(std::get<SE2>(h.landmarkTruth[i].state).equals(scenario.objects[i].pose, 1e-15));
      EXPECT_EQ(h.landmarkPriors[i].covariance, Matrix(scenario.priors.objectCovariance));
    }
    ASSERT_EQ(log.steps.size(), 31u);
    EXPECT_TRUE(truePose(log.steps[0]).equals(scenario.start, 1e-15));
    EXPECT_TRUE(log.steps[0].detections.empty());
    EXPECT_FALSE(log.steps[0].odometry);
    for (std::size_t k = 1; k < log.steps.size(); ++k) {
      EXPECT_EQ(log.steps[k].time, static_cast<double>(k));
      ASSERT_TRUE(log.steps[k].odometry);
      EXPECT_EQ(log.steps[k].odometry->covariance, Matrix(scenario.motion.covariance));
      for (std::size_t i = 0; i + 1 < log.steps[k].detections.size(); ++i) {
        EXPECT_LE(log.steps[k].detections[i].geometry(1), log.steps[k].detections[i + 1].geometry(1));
      }
    }
  }
}

TEST(Aliased2d, PriorMeansAreTheTruthWhenAskedFor) {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  scenario.priors.poseMean = PoseMean::Start;
  scenario.priors.objectMeans = ObjectMeans::Truth;
  const MeasurementLog log = simulateAliased2dTrack(scenario, 1, 0, 3);
  EXPECT_TRUE(std::get<SE2>(log.header.initialPose->mean).equals(scenario.start, 0.0));
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_TRUE(std::get<SE2>(log.header.landmarkPriors[i].mean).equals(scenario.objects[i].pose, 0.0));
  }
}

TEST(Aliased2d, ByDefaultEveryTrackStartsFromTheStartAsPaperAWithObjectMeansDrawn) {
  const Aliased2dScenario scenario = defaultAliased2dScenario();
  for (int track = 0; track < 3; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(scenario, 7, track, 2, 3);
    EXPECT_TRUE(std::get<SE2>(log.header.initialPose->mean).equals(scenario.start, 0.0));
    EXPECT_FALSE(std::get<SE2>(log.header.landmarkPriors[0].mean).equals(scenario.objects[0].pose, 1e-6));
  }
}

TEST(Aliased2d, TheObjectMeansDoNotDependOnHowTheFirstPoseMeanIsChosen) {
  Aliased2dScenario start = defaultAliased2dScenario(), sampled = start;
  start.priors.poseMean = PoseMean::Start;
  sampled.priors.poseMean = PoseMean::Sampled;
  const MeasurementLog a = simulateAliased2dTrack(start, 5, 0, 3);
  const MeasurementLog b = simulateAliased2dTrack(sampled, 5, 0, 3);
  EXPECT_FALSE(std::get<SE2>(b.header.initialPose->mean).equals(sampled.start, 1e-6));
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_TRUE(std::get<SE2>(a.header.landmarkPriors[i].mean).equals(std::get<SE2>(b.header.landmarkPriors[i].mean), 0.0));
  }
}

TEST(Aliased2d, NoiseMatchesTheStatedCovariances) {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  scenario.priors.poseMean = PoseMean::Sampled;  // so that the first pose's prior mean is drawn too
  const AnalyticViewpointClassifier classifier(scenario.alpha, scenario.sharpness);
  const RangeBearingSensor2 sensor(scenario.sensor.bodyToSensor);
  MomentCheck motion(3), geometry(2), scores(2), objectPriors(3), posePriors(3);
  const int tracks = 1500;
  for (int track = 0; track < tracks; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(scenario, 99, track, 10, tracks);
    posePriors.add(SE2::Log(scenario.start.between(std::get<SE2>(log.header.initialPose->mean))));
    for (std::size_t i = 0; i < scenario.objects.size(); ++i) {
      objectPriors.add(SE2::Log(scenario.objects[i].pose.between(std::get<SE2>(log.header.landmarkPriors[i].mean))));
    }
    for (std::size_t k = 1; k < log.steps.size(); ++k) {
      const SE2 previous = truePose(log.steps[k - 1]);
      const SE2 current = truePose(log.steps[k]);
      const SE2& action = std::get<SE2>(log.steps[k].odometry->increment);
      motion.add(SE2::Log(previous.compose(action).between(current)));
      for (const Detection& detection : log.steps[k].detections) {
        const Aliased2dObject& object = objectById(scenario, *detection.truthId);
        const Vector2 predicted = sensor.predict(current, object.pose.translation());
        geometry.add(RangeBearingSensor2::difference(Vector2(detection.geometry), predicted));
        const double theta = viewpointAngle(current.compose(scenario.sensor.bodyToSensor), object.pose);
        scores.add(*detection.classVector - classifier.mean(object.classIndex, theta));
      }
    }
  }
  EXPECT_GT(geometry.count(), 5000);
  motion.expectMoments(scenario.motion.covariance, 5.0, "motion noise");
  geometry.expectMoments(scenario.sensor.covariance, 5.0, "range-bearing noise");
  scores.expectMoments(classifier.covariance(0, 0.0), 5.0, "classifier scores");
  objectPriors.expectMoments(scenario.priors.objectCovariance, 5.0, "object prior means");
  posePriors.expectMoments(scenario.priors.initialPoseCovariance, 5.0, "initial pose prior mean");
}

TEST(Aliased2d, DetectionsAreExactlyTheVisibleObjects) {
  const Aliased2dScenario scenario = defaultAliased2dScenario();
  const VisibilityModel2 visibility = VisibilityModel2(scenario.sensor.fieldOfView, scenario.sensor.maxRange);
  int detections = 0, missed = 0;
  for (int track = 0; track < 100; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(scenario, 5, track, 15, 100);
    for (std::size_t k = 1; k < log.steps.size(); ++k) {
      const SE2 pose = truePose(log.steps[k]);
      std::set<int> detected;
      for (const Detection& detection : log.steps[k].detections) {
        ASSERT_TRUE(detection.truthId);
        EXPECT_TRUE(detected.insert(*detection.truthId).second) << "an object detected twice";
        const Point2 p = pose.transformTo(objectById(scenario, *detection.truthId).pose.translation());
        EXPECT_LE(p.norm(), scenario.sensor.maxRange);
        EXPECT_LE(std::abs(std::atan2(p.y(), p.x())), scenario.sensor.fieldOfView / 2.0);
      }
      // Every visible object is detected, except where the noisy range came out ≤ 0 (possible only within a
      // few range sigmas of the sensor; MeasurementSampling.h).
      for (const Aliased2dObject& object : scenario.objects) {
        if (!visibility.visible(pose, object.pose.translation()) || detected.count(object.id)) continue;
        const double range = pose.transformTo(object.pose.translation()).norm();
        EXPECT_LT(range, 5.0 * std::sqrt(scenario.sensor.covariance(0, 0))) << "track " << track << " step " << k;
        ++missed;
      }
      detections += static_cast<int>(detected.size());
    }
  }
  EXPECT_GT(detections, 1000);
  EXPECT_LT(missed, detections / 200 + 1);
}

TEST(Aliased2d, TracksFanOutFromTheStartAndStayNearTheArena) {
  const Aliased2dScenario scenario = defaultAliased2dScenario();
  std::set<std::pair<long, long>> ends;
  for (int track = 0; track < 50; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(scenario, 1, track, 60, 50);
    EXPECT_TRUE(truePose(log.steps.front()).equals(scenario.start, 0.0));
    for (const TimeStep& step : log.steps) {
      // Outside the arena the policy turns back at max_turn per step: the robot strays at most one turning
      // circle (radius step / max_turn) beyond it.
      const double margin = 2.0 * scenario.motion.stepLength / scenario.motion.maxTurn + 1.0;
      const double distance = (truePose(step).translation() - scenario.motion.arenaCenter).norm();
      if (step.time > 0.0) {
        EXPECT_LT(distance, std::max(scenario.motion.arenaRadius + margin,
                                     (scenario.start.translation() - scenario.motion.arenaCenter).norm() + 1.0));
      }
    }
    const Point2 end = truePose(log.steps.back()).translation();
    ends.insert({std::lround(end.x()), std::lround(end.y())});
  }
  EXPECT_GT(ends.size(), 20u);  // 50 different tracks, not one
}

TEST(Aliased2d, TheControlPolicyTurnsBackOutsideTheArena) {
  const Aliased2dScenario scenario = defaultAliased2dScenario();
  const Aliased2dMotion& motion = scenario.motion;
  std::mt19937 rng(1);
  // Far east of the arena heading east: the turn is the largest allowed, toward the centre (left or right).
  const SE2 away(motion.arenaCenter.x() + 3.0 * motion.arenaRadius, motion.arenaCenter.y() + 1.0, 0.0);
  const SE2 action = aliased2dControl(scenario, away, rng);
  EXPECT_NEAR(std::abs(action.theta()), motion.maxTurn, 1e-12);
  EXPECT_NEAR(SE2::Log(action)(0), motion.stepLength, 1e-12);
  // Inside: uniform turns within the limit, both signs.
  double lowest = 0.0, highest = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const SE2 centre(motion.arenaCenter.x(), motion.arenaCenter.y(), 0.3);
    const double turn = aliased2dControl(scenario, centre, rng).theta();
    EXPECT_LE(std::abs(turn), motion.maxTurn);
    lowest = std::min(lowest, turn);
    highest = std::max(highest, turn);
  }
  EXPECT_LT(lowest, -0.9 * motion.maxTurn);
  EXPECT_GT(highest, 0.9 * motion.maxTurn);
}

TEST(Aliased2d, TracksKeepClearOfTheObjects) {
  const Aliased2dScenario scenario = defaultAliased2dScenario();
  double least = 1e9;
  for (int track = 0; track < 100; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(scenario, 2, track, 60, 100);
    for (const TimeStep& step : log.steps) {
      for (const Aliased2dObject& object : scenario.objects) {
        least = std::min(least, (truePose(step).translation() - object.pose.translation()).norm());
      }
    }
  }
  // The policy checks the commanded arc; the motion noise (σ ≈ 3 cm per step) may take the robot a little closer.
  EXPECT_GT(least, 0.9 * scenario.motion.clearance);
  EXPECT_LT(least, 1.5 * scenario.motion.clearance);  // and it does pass close by
}

TEST(Aliased2d, StepsMustBePositive) {
  EXPECT_THROW(simulateAliased2dTrack(defaultAliased2dScenario(), 1, 0, 0), std::invalid_argument);
  Aliased2dScenario bad = defaultAliased2dScenario();
  bad.alpha = 2.0;
  EXPECT_THROW(simulateAliased2dTrack(bad, 1, 0, 5), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
