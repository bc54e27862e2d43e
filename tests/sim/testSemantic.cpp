// The semantic simulator (paper B style): determinism, valid logs in 2D and 3D, odometry and sensor noise
// against the stated covariances, the misclassification rate, clutter (Poisson count, uniform in the field of
// view), detections only inside the field of view and range, and input from the KITTI 00 trajectory.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>

#include "../support/TestData.h"
#include "SimTesting.h"
#include "semslam/io/KittiFormat.h"
#include "semslam/core/InputError.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/models/RangeBearingElevationSensor3.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/VisibilityModel.h"
#include "semslam/sim/Clutter.h"
#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"
#include "semslam/sim/SimulationStreams.h"
#include "semslam/sim/TrajectoryInput.h"

namespace semslam {
namespace {

using test::MomentCheck;
using test::ScratchFolder;

constexpr double kPi = std::numbers::pi;

SimTrajectory path(int dimension, PathShape shape = PathShape::Loop, int steps = 200, std::uint64_t seed = 1) {
  PathOptions options;
  options.shape = shape;
  options.dimension = dimension;
  options.steps = steps;
  std::mt19937 rng = simulationStream(seed, 0, SimStream::Path);
  return generatePath(options, rng);
}

Point2 landmark2(const LogHeader& header, int id) { return std::get<Point2>(header.landmarkTruth.at(id).state); }
Point3 landmark3(const LogHeader& header, int id) { return std::get<Point3>(header.landmarkTruth.at(id).state); }

TEST(SemanticSim, SameSeedSameBytesDifferentSeedDifferentBytes) {
  ScratchFolder folder;
  SemanticSimOptions options;
  options.clutter = 0.5;
  for (int dimension : {2, 3}) {
    const SimTrajectory truth = path(dimension);
    const std::string a = test::logBytes(simulateSemantic(truth, options, 4), folder, "a.jsonl");
    const std::string b = test::logBytes(simulateSemantic(truth, options, 4), folder, "b.jsonl");
    const std::string c = test::logBytes(simulateSemantic(truth, options, 5), folder, "c.jsonl");
    EXPECT_EQ(a, b) << dimension << "D";
    EXPECT_NE(a, c) << dimension << "D";
  }
  // The generated path itself is seeded.
  const SimTrajectory p1 = path(2, PathShape::Loop, 50, 1), p2 = path(2, PathShape::Loop, 50, 1),
                      p3 = path(2, PathShape::Loop, 50, 2);
  EXPECT_TRUE(std::get<SE2>(p1.poses[20]).equals(std::get<SE2>(p2.poses[20]), 0.0));
  EXPECT_FALSE(std::get<SE2>(p1.poses[20]).equals(std::get<SE2>(p3.poses[20]), 1e-6));
}

TEST(SemanticSim, LogsReadBackIn2DAnd3D) {
  ScratchFolder folder;
  SemanticSimOptions options;
  options.clutter = 1.0;
  options.classes = 3;
  options.detectionProbability = 0.9;
  for (int dimension : {2, 3}) {
    for (PathShape shape : {PathShape::Loop, PathShape::Lawnmower}) {
      const std::string file = folder.file("log.jsonl");
      writeMeasurementLog(file, simulateSemantic(path(dimension, shape), options, 8));
      const MeasurementLog log = readMeasurementLog(file);
      EXPECT_EQ(log.header.dimension, dimension);
      EXPECT_EQ(log.header.classes, 3);
      EXPECT_EQ(log.header.semantic, SemanticKind::Label);
      EXPECT_EQ(log.header.classifier.kind, ClassifierModelSpec::Kind::Categorical);
      EXPECT_EQ(log.header.classifier.misclassification, options.misclassification);
      EXPECT_EQ(log.header.sensor.kind, dimension == 2 ? SensorKind::RangeBearing : SensorKind::RangeBearingElevation);
      EXPECT_FALSE(log.header.landmarksHavePose);
      EXPECT_EQ(log.header.landmarkTruth.size(), 20u);  // 0.1 per metre of a 200 m path
      EXPECT_EQ(log.steps.size(), 201u);
      std::size_t detections = 0, clutter = 0;
      for (const TimeStep& step : log.steps) {
        detections += step.detections.size();
        for (const Detection& d : step.detections) clutter += d.truthId == kNotALandmark ? 1 : 0;
      }
      EXPECT_GT(detections - clutter, 100u);
      EXPECT_GT(clutter, 100u);
    }
  }
}

TEST(SemanticSim, GeneratedPathsHaveTheStepLengthAndStartAtTheOrigin) {
  for (int dimension : {2, 3}) {
    for (PathShape shape : {PathShape::Loop, PathShape::Lawnmower}) {
      const SimTrajectory p = path(dimension, shape, 300);
      ASSERT_EQ(p.poses.size(), 301u);
      for (std::size_t k = 1; k < p.poses.size(); ++k) {
        EXPECT_EQ(p.times[k], static_cast<double>(k));
        const Vector3 a = dimension == 2
                              ? Vector3(std::get<SE2>(p.poses[k - 1]).x(), std::get<SE2>(p.poses[k - 1]).y(), 0)
                              : Vector3(std::get<SE3>(p.poses[k - 1]).translation());
        const Vector3 b = dimension == 2 ? Vector3(std::get<SE2>(p.poses[k]).x(), std::get<SE2>(p.poses[k]).y(), 0)
                                         : Vector3(std::get<SE3>(p.poses[k]).translation());
        // Chords of a curve are a little shorter than its arcs.
        EXPECT_NEAR((b - a).norm(), 1.0, 0.02) << k;
      }
      if (dimension == 2) {
        EXPECT_TRUE(std::get<SE2>(p.poses[0]).equals(SE2(), 1e-9));
      } else {
        EXPECT_LT(std::get<SE3>(p.poses[0]).translation().norm(), 1e-9);
      }
    }
  }
  // A loop driven twice comes back to where it started.
  const SimTrajectory loop = path(2, PathShape::Loop, 200);
  EXPECT_LT((std::get<SE2>(loop.poses[200]).translation() - std::get<SE2>(loop.poses[0]).translation()).norm(), 1e-6);
  EXPECT_LT((std::get<SE2>(loop.poses[100]).translation() - std::get<SE2>(loop.poses[0]).translation()).norm(), 1e-6);
}

TEST(SemanticSim, OdometryNoiseIsTheScaledBaseline) {
  for (int dimension : {2, 3}) {
    const SimTrajectory truth = path(dimension, PathShape::Loop, 20000);
    for (double scale : {1.0, 4.0}) {
      SemanticSimOptions options;
      options.odomNoiseScale = scale;
      options.landmarks = 1;
      const MeasurementLog log = simulateSemantic(truth, options, 21);
      const Matrix expected = scale * scale * baselineOdometryCovariance(dimension);
      MomentCheck noise(dimension == 2 ? 3 : 6);
      for (std::size_t k = 1; k < log.steps.size(); ++k) {
        const Odometry& odometry = *log.steps[k].odometry;
        EXPECT_EQ(odometry.covariance, expected);
        if (dimension == 2) {
          const SE2 trueIncrement = std::get<SE2>(truth.poses[k - 1]).between(std::get<SE2>(truth.poses[k]));
          noise.add(SE2::Log(trueIncrement.between(std::get<SE2>(odometry.increment))));
        } else {
          const SE3 trueIncrement = std::get<SE3>(truth.poses[k - 1]).between(std::get<SE3>(truth.poses[k]));
          noise.add(SE3::Log(trueIncrement.between(std::get<SE3>(odometry.increment))));
        }
      }
      noise.expectMoments(expected, 5.0, std::to_string(dimension) + "D odometry, scale " + std::to_string(scale));
    }
  }
}

TEST(SemanticSim, OdometryCovarianceScaleAndExactOdometry) {
  const SimTrajectory truth = path(2, PathShape::Loop, 50);
  SemanticSimOptions options;
  options.odomNoiseScale = 0.0;
  const MeasurementLog exact = simulateSemantic(truth, options, 2);
  for (std::size_t k = 1; k < exact.steps.size(); ++k) {
    const SE2 trueIncrement = std::get<SE2>(truth.poses[k - 1]).between(std::get<SE2>(truth.poses[k]));
    EXPECT_TRUE(std::get<SE2>(exact.steps[k].odometry->increment).equals(trueIncrement, 1e-12));
    EXPECT_EQ(exact.steps[k].odometry->covariance, 1e-6 * baselineOdometryCovariance(2));
  }
  options.odomNoiseScale = 3.0;
  options.odomCovarianceScale = 1.0;  // noise larger than the log admits, as in paper B's robustness study
  const MeasurementLog mismatched = simulateSemantic(truth, options, 2);
  EXPECT_EQ(mismatched.steps[1].odometry->covariance, baselineOdometryCovariance(2));
}

TEST(SemanticSim, SensorNoiseMatchesItsCovariance) {
  for (int dimension : {2, 3}) {
    const SimTrajectory truth = path(dimension, PathShape::Loop, 3000);
    SemanticSimOptions options;
    options.landmarkDensity = 0.3;
    const MeasurementLog log = simulateSemantic(truth, options, 31);
    Matrix expected = Matrix::Zero(dimension, dimension);
    expected(0, 0) = options.rangeSigma * options.rangeSigma;
    expected(1, 1) = options.bearingSigma * options.bearingSigma;
    if (dimension == 3) expected(2, 2) = options.elevationSigma * options.elevationSigma;
    MomentCheck noise(dimension);
    for (std::size_t k = 0; k < log.steps.size(); ++k) {
      for (const Detection& d : log.steps[k].detections) {
        EXPECT_EQ(d.covariance, expected);
        if (dimension == 2) {
          const Vector2 predicted =
              RangeBearingSensor2().predict(std::get<SE2>(truth.poses[k]), landmark2(log.header, *d.truthId));
          noise.add(RangeBearingSensor2::difference(Vector2(d.geometry), predicted));
        } else {
          const Vector3 predicted =
              RangeBearingElevationSensor3().predict(std::get<SE3>(truth.poses[k]), landmark3(log.header, *d.truthId));
          noise.add(RangeBearingElevationSensor3::difference(Vector3(d.geometry), predicted));
        }
      }
    }
    EXPECT_GT(noise.count(), 5000);
    noise.expectMoments(expected, 5.0, std::to_string(dimension) + "D sensor noise");
  }
}

TEST(SemanticSim, LabelsAreWrongAtTheMisclassificationRate) {
  const SimTrajectory truth = path(2, PathShape::Loop, 3000);
  for (int classes : {2, 4}) {
    SemanticSimOptions options;
    options.classes = classes;
    options.misclassification = 0.2;
    options.landmarkDensity = 0.3;
    const MeasurementLog log = simulateSemantic(truth, options, 41);
    std::map<int, int> wrongByLabel;
    int total = 0, wrong = 0;
    for (const TimeStep& step : log.steps) {
      for (const Detection& d : step.detections) {
        const int truthClass = log.header.landmarkTruth.at(*d.truthId).classIndex;
        ++total;
        if (*d.label != truthClass) {
          ++wrong;
          ++wrongByLabel[*d.label];
        }
      }
    }
    const double p = 0.2;
    EXPECT_NEAR(static_cast<double>(wrong) / total, p, 5.0 * std::sqrt(p * (1 - p) / total)) << classes;
    EXPECT_EQ(static_cast<int>(wrongByLabel.size()), classes);  // wrong labels go to every class
  }
}

TEST(SemanticSim, DetectionsOnlyInsideTheFieldOfViewAndRange) {
  for (int dimension : {2, 3}) {
    SemanticSimOptions options;
    options.clutter = 2.0;
    options.fieldOfView = 1.2;
    options.maxRange = 8.0;
    options.detectionProbability = 1.0;
    const SimTrajectory truth = path(dimension, PathShape::Lawnmower, 1000);
    const MeasurementLog log = simulateSemantic(truth, options, 51);
    int detections = 0, clutter = 0;
    double clutterBearingSum = 0.0;
    for (std::size_t k = 0; k < log.steps.size(); ++k) {
      std::set<int> detected;
      for (const Detection& d : log.steps[k].detections) {
        if (*d.truthId == kNotALandmark) {
          ++clutter;
          // Exact points inside the field of view and range.
          EXPECT_GT(d.geometry(0), 0.0);
          EXPECT_LE(d.geometry(0), options.maxRange);
          if (dimension == 2) {
            EXPECT_LE(std::abs(d.geometry(1)), options.fieldOfView / 2.0 + 1e-12);
          } else {
            const Vector3 p = RangeBearingElevationSensor3().backProject(SE3(), Vector3(d.geometry));
            EXPECT_LE(std::atan2(p.tail<2>().norm(), p.x()), options.fieldOfView / 2.0 + 1e-9);
          }
          clutterBearingSum += d.geometry(1);
          continue;
        }
        ++detections;
        detected.insert(*d.truthId);
        if (dimension == 2) {
          const Point2 p = std::get<SE2>(truth.poses[k]).transformTo(landmark2(log.header, *d.truthId));
          EXPECT_LE(p.norm(), options.maxRange);
          EXPECT_LE(std::abs(std::atan2(p.y(), p.x())), options.fieldOfView / 2.0);
        } else {
          const Point3 p = std::get<SE3>(truth.poses[k]).transformTo(landmark3(log.header, *d.truthId));
          EXPECT_LE(p.norm(), options.maxRange);
          EXPECT_LE(std::atan2(p.tail<2>().norm(), p.x()), options.fieldOfView / 2.0);
        }
      }
      // Every visible landmark is detected (detection probability 1).
      std::set<int> visible;
      for (const LandmarkTruth& landmark : log.header.landmarkTruth) {
        const bool seen = dimension == 2
                              ? VisibilityModel2(options.fieldOfView, options.maxRange)
                                    .visible(std::get<SE2>(truth.poses[k]), std::get<Point2>(landmark.state))
                              : VisibilityModel3(options.fieldOfView, options.maxRange)
                                    .visible(std::get<SE3>(truth.poses[k]), std::get<Point3>(landmark.state));
        if (seen) visible.insert(landmark.id);
      }
      EXPECT_EQ(detected, visible) << "step " << k;
    }
    EXPECT_GT(detections, 300);
    // Clutter: Poisson(2) per step.
    const double n = static_cast<double>(log.steps.size());
    EXPECT_NEAR(clutter / n, options.clutter, 5.0 * std::sqrt(options.clutter / n));
    EXPECT_NEAR(clutterBearingSum / clutter, 0.0, 0.1);
  }
}

TEST(SemanticSim, ClutterIsUniformOverTheFieldOfView) {
  std::mt19937 rng(61);
  const int n = 200000;
  const double fov = 1.5, range = 10.0;
  // 2D: area-uniform: P(r ≤ R/2) = 1/4, bearing uniform: P(bearing > fov/4) = 1/4.
  int inner = 0, right = 0;
  for (int i = 0; i < n; ++i) {
    const Vector2 z = uniformRangeBearing(fov, range, rng);
    ASSERT_GT(z(0), 0.0);
    ASSERT_LE(z(0), range);
    ASSERT_LE(std::abs(z(1)), fov / 2.0);
    inner += z(0) <= range / 2.0;
    right += z(1) > fov / 4.0;
  }
  const double sd = std::sqrt(0.25 * 0.75 / n);
  EXPECT_NEAR(inner / double(n), 0.25, 5 * sd);
  EXPECT_NEAR(right / double(n), 0.25, 5 * sd);
  // 3D: volume-uniform: P(r ≤ R/2) = 1/8; the solid angle inside half the cone angle a/2 is
  // (1 − cos(a/2)) / (1 − cos a).
  int inner3 = 0, core = 0;
  const double a = fov / 2.0;
  for (int i = 0; i < n; ++i) {
    const Vector3 z = uniformRangeBearingElevation(fov, range, rng);
    const Vector3 p = RangeBearingElevationSensor3().backProject(SE3(), z);
    const double off = std::atan2(p.tail<2>().norm(), p.x());
    ASSERT_LE(off, a + 1e-12);
    inner3 += z(0) <= range / 2.0;
    core += off <= a / 2.0;
  }
  EXPECT_NEAR(inner3 / double(n), 0.125, 5 * std::sqrt(0.125 * 0.875 / n));
  const double pCore = (1 - std::cos(a / 2)) / (1 - std::cos(a));
  EXPECT_NEAR(core / double(n), pCore, 5 * std::sqrt(pCore * (1 - pCore) / n));
  // Poisson: mean and variance λ.
  for (double lambda : {0.3, 4.0, 30.0}) {
    double sum = 0.0, squares = 0.0;
    const int draws = 100000;
    for (int i = 0; i < draws; ++i) {
      const double k = samplePoisson(lambda, rng);
      sum += k;
      squares += k * k;
    }
    const double mean = sum / draws;
    EXPECT_NEAR(mean, lambda, 5.0 * std::sqrt(lambda / draws));
    EXPECT_NEAR(squares / draws - mean * mean, lambda, 5.0 * lambda * std::sqrt((2.0 + 1.0 / lambda) / draws));
  }
  EXPECT_EQ(samplePoisson(0.0, rng), 0);
  EXPECT_THROW(samplePoisson(-1.0, rng), std::invalid_argument);
  EXPECT_THROW(uniformRangeBearing(fov, 0.0, rng), std::invalid_argument);
}

TEST(SemanticSim, KittiSequence00AsTheTrajectory) {
  SEMSLAM_REQUIRE_DATA(file, "kitti-odometry-poses/00.txt");
  const Trajectory kitti = readKittiTrajectory(file.string());
  ScratchFolder folder;
  for (int dimension : {3, 2}) {
    TrajectoryInputOptions input;
    input.dimension = dimension;
    input.frame = TrajectoryFrame::Camera;
    const SimTrajectory truth = simTrajectoryFromFile(kitti, input, file.string());
    ASSERT_EQ(truth.poses.size(), kitti.size());
    EXPECT_EQ(truth.times.front(), kitti.timestamp(0));
    EXPECT_EQ(truth.times.back(), kitti.timestamp(kitti.size() - 1));
    SemanticSimOptions options;
    options.maxRange = 25.0;
    options.clutter = 0.2;
    const std::string out = folder.file("kitti.jsonl");
    writeMeasurementLog(out, simulateSemantic(truth, options, 1));
    const MeasurementLog log = readMeasurementLog(out);
    EXPECT_EQ(log.steps.size(), kitti.size());
    EXPECT_GT(log.header.landmarkTruth.size(), 300u);  // 0.1 per metre of a 3.7 km drive
    std::size_t detections = 0;
    for (const TimeStep& step : log.steps) detections += step.detections.size();
    EXPECT_GT(detections, kitti.size());
    if (dimension == 3) {
      // Body frame, z up: the car's up axis stays near the world's, and the road stays within a few metres
      // of the start's height; forward is the camera's z axis.
      for (std::size_t k = 0; k < truth.poses.size(); k += 50) {
        const SE3& pose = std::get<SE3>(truth.poses[k]);
        EXPECT_GT(pose.rotation().matrix()(2, 2), 0.95) << k;
        EXPECT_LT(std::abs(pose.translation().z()), 30.0) << k;
        const Vector3 forward = pose.rotation().matrix().col(0);
        const Vector3 cameraForward = kitti.pose(k).rotation().matrix().col(2);
        EXPECT_NEAR(forward.x(), cameraForward.z(), 1e-3);  // body x = camera z, world re-axed the same way
      }
    }
  }
}

TEST(SemanticSim, TrajectoryInputStrideStepsAndRepeatedTimes) {
  std::vector<SE3> poses;
  std::vector<double> times;
  for (int i = 0; i < 10; ++i) {
    poses.emplace_back(SO3::fromAxisAngle(Vector3::UnitZ(), 0.1 * i), Point3(i, 0.0, 0.0));
    times.push_back(i < 3 ? 0.0 : i);  // three equal stamps
  }
  const Trajectory trajectory(times, poses);
  TrajectoryInputOptions input;
  input.dimension = 2;
  const SimTrajectory all = simTrajectoryFromFile(trajectory, input, "t.txt");
  EXPECT_EQ(all.poses.size(), 8u);  // the two repeats of time 0 are skipped
  EXPECT_NEAR(std::get<SE2>(all.poses[1]).theta(), 0.3, 1e-12);
  input.stride = 3;
  input.maxSteps = 2;
  const SimTrajectory strided = simTrajectoryFromFile(trajectory, input, "t.txt");
  ASSERT_EQ(strided.poses.size(), 3u);  // poses 0, 3, 6
  EXPECT_EQ(strided.times, (std::vector<double>{0.0, 3.0, 6.0}));
  input.stride = 20;
  EXPECT_THROW(simTrajectoryFromFile(trajectory, input, "t.txt"), InputError);
}

TEST(SemanticSim, InvalidOptionsAreRejected) {
  const SimTrajectory truth = path(2, PathShape::Loop, 10);
  const auto rejects = [&truth](const std::function<void(SemanticSimOptions&)>& change) {
    SemanticSimOptions options;
    change(options);
    EXPECT_THROW(simulateSemantic(truth, options, 1), std::invalid_argument);
  };
  rejects([](SemanticSimOptions& o) { o.classes = 0; });
  rejects([](SemanticSimOptions& o) { o.classes = 1; });  // misclassification 0.1 with one class
  rejects([](SemanticSimOptions& o) { o.misclassification = 1.0; });
  rejects([](SemanticSimOptions& o) { o.clutter = -1.0; });
  rejects([](SemanticSimOptions& o) {
    o.clutter = 1.0;
    o.maxRange = 0.0;
  });
  rejects([](SemanticSimOptions& o) { o.fieldOfView = 7.0; });
  rejects([](SemanticSimOptions& o) { o.rangeSigma = 0.0; });
  rejects([](SemanticSimOptions& o) { o.odomNoiseScale = -1.0; });
  rejects([](SemanticSimOptions& o) { o.odomCovarianceScale = 0.0; });
  rejects([](SemanticSimOptions& o) { o.detectionProbability = 1.5; });
  rejects([](SemanticSimOptions& o) { o.minOffset = 5.0, o.maxOffset = 1.0; });
  SemanticSimOptions fine;
  fine.classes = 1;
  fine.misclassification = 0.0;
  EXPECT_NO_THROW(simulateSemantic(truth, fine, 1));
}

}  // namespace
}  // namespace semslam
