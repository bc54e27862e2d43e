#include "semslam/sim/Aliased2dSimulator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "semslam/models/AnalyticViewpointClassifier.h"
#include "semslam/models/Angle.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/Viewpoint.h"
#include "semslam/models/VisibilityModel.h"
#include "semslam/sim/MeasurementSampling.h"
#include "semslam/sim/SimulationStreams.h"

namespace semslam {

namespace {

/// truth · Exp(δ), δ ~ N(0, Σ).
SE2 perturbed(const SE2& truth, const Matrix3& covariance, std::mt19937& rng) {
  const Vector delta = sampleGaussian(Vector::Zero(3), covariance, rng);
  return truth.retract(Vector3(delta));
}

std::string sourceText(const Aliased2dScenario& scenario, std::uint64_t seed, int track, int tracks, int steps) {
  std::ostringstream text;
  text.precision(17);
  text << "semslam simulate aliased2d: scenario '" << scenario.name << "', seed " << seed << ", track " << track
       << " of " << tracks << ", " << steps << " steps, alpha " << scenario.alpha << ", sharpness "
       << scenario.sharpness << ", prior mean of the first pose " << poseMeanName(scenario.priors.poseMean)
       << ", of the objects " << objectMeansName(scenario.priors.objectMeans);
  return text.str();
}

}  // namespace

SE2 aliased2dControl(const Aliased2dScenario& scenario, const SE2& pose, std::mt19937& rng) {
  constexpr int kProposals = 17;
  const Aliased2dMotion& motion = scenario.motion;
  // The least distance to any object along the arc continued for three steps at the same turn rate (a robot
  // that turns at most maxTurn per step must look ahead to stay clear).
  const auto distanceToObjects = [&scenario, &pose](const Vector3& xi) {
    double least = std::numeric_limits<double>::infinity();
    for (const double fraction : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) {
      const Point2 p = pose.compose(SE2::Exp(fraction * xi)).translation();
      for (const Aliased2dObject& object : scenario.objects) {
        least = std::min(least, (object.pose.translation() - p).norm());
      }
    }
    return least;
  };
  Vector3 best = Vector3::Zero();
  double bestDistance = -1.0;
  for (int proposal = 0; proposal < kProposals; ++proposal) {
    const double u = uniform01(rng);
    double turn = motion.maxTurn * (2.0 * u - 1.0);
    const Point2 toCenter = motion.arenaCenter - pose.translation();
    if (proposal == 0 && toCenter.norm() > motion.arenaRadius) {
      const double bearing = wrapAngle(std::atan2(toCenter.y(), toCenter.x()) - pose.theta());
      turn = std::clamp(bearing, -motion.maxTurn, motion.maxTurn);
    }
    const Vector3 xi(motion.stepLength, 0.0, turn);
    const double distance = distanceToObjects(xi);
    if (distance >= motion.clearance) return SE2::Exp(xi);
    if (distance > bestDistance) {
      bestDistance = distance;
      best = xi;
    }
  }
  return SE2::Exp(best);
}

MeasurementLog simulateAliased2dTrack(const Aliased2dScenario& scenario, std::uint64_t seed, int track, int steps,
                                      int tracks) {
  validateAliased2dScenario(scenario);
  if (steps < 1) throw std::invalid_argument("aliased2d: steps must be >= 1, found " + std::to_string(steps));
  if (track < 0) throw std::invalid_argument("aliased2d: the track index must be >= 0");
  const auto trackIndex = static_cast<std::uint32_t>(track);
  std::mt19937 controls = simulationStream(seed, trackIndex, SimStream::Controls);
  std::mt19937 motionNoise = simulationStream(seed, trackIndex, SimStream::MotionNoise);
  std::mt19937 priors = simulationStream(seed, trackIndex, SimStream::Priors);
  std::mt19937 geometryNoise = simulationStream(seed, trackIndex, SimStream::Geometry);
  std::mt19937 semanticNoise = simulationStream(seed, trackIndex, SimStream::Semantic);

  const AnalyticViewpointClassifier classifier(scenario.alpha, scenario.sharpness, scenario.classes);
  const RangeBearingSensor2 sensor(scenario.sensor.bodyToSensor);
  const VisibilityModel2 visibility(scenario.sensor.fieldOfView, scenario.sensor.maxRange,
                                    scenario.sensor.bodyToSensor);
  const Matrix measurementCovariance = scenario.sensor.covariance;
  const Matrix motionCovariance = scenario.motion.covariance;

  MeasurementLog log;
  LogHeader& header = log.header;
  header.dimension = 2;
  header.classes = scenario.classes;
  header.semantic = SemanticKind::Scores;
  header.classifier.kind = ClassifierModelSpec::Kind::ViewpointGaussian;
  header.classifier.alpha = scenario.alpha;
  header.classifier.sharpness = scenario.sharpness;
  header.sensor.kind = SensorKind::RangeBearing;
  header.sensor.bodyToSensor = scenario.sensor.bodyToSensor;
  header.sensor.maxRange = scenario.sensor.maxRange;
  header.sensor.fieldOfView = scenario.sensor.fieldOfView;
  header.landmarksHavePose = true;
  // Prior draws: the initial pose first, then the objects in the scenario's order. The first pose's draw is made
  // whatever its mean's choice, so that the objects' means do not depend on that choice.
  PosePrior initial;
  const SE2 sampledStart = perturbed(scenario.start, scenario.priors.initialPoseCovariance, priors);
  initial.mean = scenario.priors.poseMean == PoseMean::Sampled ? sampledStart : scenario.start;
  initial.covariance = scenario.priors.initialPoseCovariance;
  header.initialPose = initial;
  for (const Aliased2dObject& object : scenario.objects) {
    LandmarkPrior prior;
    prior.id = object.id;
    prior.mean = scenario.priors.objectMeans == ObjectMeans::Sampled
                     ? perturbed(object.pose, scenario.priors.objectCovariance, priors)
                     : object.pose;
    prior.covariance = scenario.priors.objectCovariance;
    header.landmarkPriors.push_back(prior);
    header.landmarkTruth.push_back(LandmarkTruth{object.id, object.classIndex, object.pose});
  }
  header.source = sourceText(scenario, seed, track, tracks, steps);

  SE2 pose = scenario.start;
  TimeStep first;
  first.time = 0.0;
  first.truePose = pose;
  log.steps.push_back(first);
  for (int k = 1; k <= steps; ++k) {
    const SE2 action = aliased2dControl(scenario, pose, controls);
    const Vector w = sampleGaussian(Vector::Zero(3), motionCovariance, motionNoise);
    pose = pose.compose(action).retract(Vector3(w));

    TimeStep step;
    step.time = k * scenario.motion.timeStep;
    step.odometry = Odometry{action, motionCovariance};
    step.truePose = pose;
    const SE2 camera = pose.compose(scenario.sensor.bodyToSensor);
    for (const Aliased2dObject& object : scenario.objects) {
      if (!visibility.visible(pose, object.pose.translation())) continue;
      const std::optional<Vector> geometry =
          sampleRangeBearing(sensor, pose, object.pose.translation(), measurementCovariance, geometryNoise);
      const double theta = viewpointAngle(camera, object.pose);
      Vector scores = classifier.sample(object.classIndex, theta, semanticNoise);
      if (!geometry) continue;
      Detection detection;
      detection.geometry = *geometry;
      detection.covariance = measurementCovariance;
      detection.classVector = std::move(scores);
      detection.truthId = object.id;
      step.detections.push_back(std::move(detection));
    }
    sortDetectionsByBearing(step.detections);
    log.steps.push_back(std::move(step));
  }
  return log;
}

}  // namespace semslam
