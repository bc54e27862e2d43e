#include "semslam/association/PreselectionRadius.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "semslam/geometry/CovarianceSpread.h"

namespace semslam {
namespace {

/// The sensor's position in the world (2 or 3 coordinates).
Vector sensorPosition(const Value& pose, const SensorSpec& sensor) {
  if (const auto* x = std::get_if<SE2>(&pose)) return x->compose(std::get<SE2>(sensor.bodyToSensor)).translation();
  return std::get<SE3>(pose).compose(std::get<SE3>(sensor.bodyToSensor)).translation();
}

}  // namespace

double semanticGateAllowance(const Vector& likelihoods) {
  if (likelihoods.size() == 0) return 0.0;
  const double largest = likelihoods.maxCoeff();
  const double labelPrior = likelihoods.mean();
  if (std::isnan(largest) || std::isnan(labelPrior) || !std::isfinite(largest)) {
    return std::numeric_limits<double>::infinity();  // no bound on the semantic term: no ball
  }
  // Every likelihood 0: P₀ falls back to 1 in the joint gate and every landmark's predictive is 0, so none passes.
  if (!(labelPrior > 0.0)) return 0.0;
  return std::max(0.0, 2.0 * std::log(largest / labelPrior));
}

double positionSpread(const Matrix& covariance, int dimension) {
  if (covariance.rows() < dimension || covariance.cols() < dimension) {
    throw std::invalid_argument("landmark covariance is smaller than its position block");
  }
  return largestStandardDeviation(covariance.topLeftCorner(dimension, dimension));
}

int gateDegreesOfFreedom(const SensorSpec& sensor, int dimension) {
  switch (sensor.kind) {
    case SensorKind::RangeBearing: return 2;
    case SensorKind::RangeBearingElevation: return 3;
    case SensorKind::RelativePosition: return dimension;
    case SensorKind::RelativePose: return dimension == 2 ? 3 : 6;
  }
  throw std::invalid_argument("unknown sensor kind");
}

std::optional<PreselectionBall> preselectionBall(const MeasurementFactory& factory, const SensorSpec& sensor,
                                                 const Value& pose, const Matrix& poseCovariance,
                                                 const Detection& detection, double threshold) {
  // §7: the bound holds for residuals that are polar or Cartesian coordinates of the landmark's position in the
  // sensor frame; a relative pose's residual is an SE(n) logarithm, which it does not cover.
  if (sensor.kind == SensorKind::RelativePose) return std::nullopt;
  if (!(threshold >= 0.0) || !std::isfinite(threshold)) return std::nullopt;
  const int d = factory.dimension();
  const int rotationDimension = d == 2 ? 1 : 3;
  if (poseCovariance.rows() != d + rotationDimension || poseCovariance.cols() != d + rotationDimension) {
    throw std::invalid_argument("pose covariance does not fit the log dimension");
  }
  const double sigmaTranslation = largestStandardDeviation(poseCovariance.topLeftCorner(d, d));
  const double sigmaRotation =
      largestStandardDeviation(poseCovariance.bottomRightCorner(rotationDimension, rotationDimension));

  const Vector b = MeasurementFactory::positionOf(factory.initialLandmark(detection, pose));
  const Vector bodyOrigin = MeasurementFactory::positionOf(pose);
  const double lever = (b - bodyOrigin).norm();  // ℓ

  const Matrix& R = detection.covariance;
  double k = 1.0, sigmaFixed = 0.0, sigmaAngular = 0.0, range = 0.0;
  if (sensor.kind == SensorKind::RelativePosition) {
    sigmaFixed = largestStandardDeviation(R);
    range = lever;  // the sensor is at the body origin
  } else {
    const int m = gateDegreesOfFreedom(sensor, d);
    k = std::sqrt(static_cast<double>(m));
    sigmaFixed = std::sqrt(std::max(R(0, 0), 0.0));
    double angular = 0.0;
    for (int i = 1; i < m; ++i) angular += std::max(R(i, i), 0.0);
    sigmaAngular = std::sqrt(angular);
    range = (b - sensorPosition(pose, sensor)).norm();  // the measured range, as back-projected
  }
  const double scale = k * std::sqrt(threshold);
  const double kappa = scale * (sigmaRotation + sigmaAngular);
  if (!(kappa < 1.0)) return std::nullopt;
  PreselectionBall ball;
  ball.center = b;
  ball.base = scale * (sigmaTranslation + sigmaRotation * lever + sigmaFixed + sigmaAngular * range) / (1.0 - kappa);
  ball.slope = scale / (1.0 - kappa);
  if (!std::isfinite(ball.base) || !std::isfinite(ball.slope)) return std::nullopt;
  return ball;
}

}  // namespace semslam
