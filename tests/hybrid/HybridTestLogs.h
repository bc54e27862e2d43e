#pragma once
// Small measurement logs for the hybrid-belief tests.

#include <cmath>

#include "semslam/hybrid/HybridOptions.h"
#include "semslam/models/MeasurementLog.h"
#include "support/GaussianDensity.h"
#include "semslam/sim/Aliased2dSimulator.h"

namespace semslam::test {

/// A linear-Gaussian toy: a robot with a (practically) known heading θ = 0 and uncertain position, point objects
/// with uncertain positions, a relative-position sensor (z = R(θ)ᵀ (l − t) + v), one step with `detections`.
inline MeasurementLog linearToyLog(const std::vector<Point2>& objectMeans, const std::vector<Vector2>& detections,
                                   double objectVariance = 0.3, double robotVariance = 0.5, double noise = 0.2) {
  MeasurementLog log;
  LogHeader& h = log.header;
  h.dimension = 2;
  h.classes = 1;
  h.sensor.kind = SensorKind::RelativePosition;
  h.sensor.bodyToSensor = SE2();
  h.landmarksHavePose = false;
  PosePrior prior;
  prior.mean = SE2(0.0, 0.0, 0.0);
  prior.covariance = Vector3(robotVariance, robotVariance, 1e-14).asDiagonal();
  h.initialPose = prior;
  for (std::size_t j = 0; j < objectMeans.size(); ++j) {
    LandmarkPrior l;
    l.id = static_cast<int>(10 + j);
    l.mean = objectMeans[j];
    l.covariance = Matrix2::Identity() * objectVariance;
    h.landmarkPriors.push_back(l);
  }
  TimeStep step;
  for (const Vector2& z : detections) {
    Detection d;
    d.geometry = z;
    d.covariance = Matrix2::Identity() * noise * noise;
    step.detections.push_back(d);
  }
  step.truePose = SE2();
  log.steps.push_back(step);
  return log;
}

/// paper A's default scenario with only its first `objects` objects.
inline Aliased2dScenario smallAliasedScenario(int objects) {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  scenario.objects.resize(static_cast<std::size_t>(objects));
  return scenario;
}

/// Closed-form weights of associating detection z with each object of the linear toy (θ = 0 exactly known):
/// z = l − t + v, so p(z | β = j) = N(z; l̄_j − t̄, Σ_t + Σ_l + R).
inline std::vector<double> closedFormWeights(const MeasurementLog& log) {
  const LogHeader& h = log.header;
  const Vector2 z = log.steps[0].detections[0].geometry;
  const Matrix2 R = log.steps[0].detections[0].covariance;
  const Vector2 t = std::get<SE2>(h.initialPose->mean).translation();
  const Matrix2 St = h.initialPose->covariance.topLeftCorner<2, 2>();
  std::vector<double> logs;
  for (const LandmarkPrior& l : h.landmarkPriors) logs.push_back(logGaussian(z, std::get<Point2>(l.mean) - t, St + l.covariance + R));
  double sum = 0.0;
  for (double& l : logs) sum += l = std::exp(l);
  for (double& l : logs) l /= sum;
  return logs;
}

inline HybridOptions unpruned(WeightMethod method, int samples = 1000) {
  HybridOptions o;
  o.useSemantics = false;
  o.weights = method;
  o.samples = samples;
  o.pruneRatio = 0.0;
  o.gateRatio = 0.0;
  o.visibility = false;
  return o;
}

}  // namespace semslam::test
