#include "semslam/sim/MeasurementSampling.h"

#include <algorithm>
#include <numbers>

#include "semslam/models/Angle.h"
#include "semslam/models/Sampling.h"

namespace semslam {

std::optional<Vector> sampleRangeBearing(const RangeBearingSensor2& sensor, const SE2& robot, const Point2& point,
                                         const Matrix& covariance, std::mt19937& rng) {
  const Vector2 predicted = sensor.predict(robot, point);
  Vector z = sampleGaussian(Vector(predicted), covariance, rng);
  if (!(z(0) > 0.0)) return std::nullopt;
  z(1) = wrapAngle(z(1));
  return z;
}

std::optional<Vector> sampleRangeBearingElevation(const RangeBearingElevationSensor3& sensor, const SE3& robot,
                                                  const Point3& point, const Matrix& covariance, std::mt19937& rng) {
  const Vector3 predicted = sensor.predict(robot, point);
  Vector z = sampleGaussian(Vector(predicted), covariance, rng);
  if (!(z(0) > 0.0)) return std::nullopt;
  z(1) = wrapAngle(z(1));
  z(2) = std::clamp(z(2), -std::numbers::pi / 2.0, std::numbers::pi / 2.0);
  return z;
}

void sortDetectionsByBearing(std::vector<Detection>& detections) {
  std::stable_sort(detections.begin(), detections.end(),
                   [](const Detection& a, const Detection& b) { return a.geometry(1) < b.geometry(1); });
}

}  // namespace semslam
