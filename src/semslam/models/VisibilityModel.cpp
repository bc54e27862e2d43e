#include "semslam/models/VisibilityModel.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace semslam {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

template <class Model, class Pose, class Point>
bool feasible(const Model& model, const Pose& robot, std::span<const Point> objects, std::span<const int> beta,
              bool distinct) {
  if (model.oneDetectionPerObject() && !distinct) return false;
  for (int b : beta) {
    if (!model.visible(robot, objects[static_cast<std::size_t>(b)])) return false;
  }
  return true;
}

}  // namespace

VisibilityLimits::VisibilityLimits(double fieldOfView, double maxRange, bool oneDetectionPerObject)
    : fieldOfView_(fieldOfView), maxRange_(maxRange), oneDetectionPerObject_(oneDetectionPerObject) {
  if (!std::isfinite(fieldOfView) || fieldOfView < 0.0) {
    throw std::invalid_argument("visibility: the field of view must be finite and >= 0 (0: all around), got " +
                                std::to_string(fieldOfView));
  }
  if (!std::isfinite(maxRange) || maxRange < 0.0) {
    throw std::invalid_argument("visibility: the maximum range must be finite and >= 0 (0: unlimited), got " +
                                std::to_string(maxRange));
  }
}

bool VisibilityLimits::visibleAt(double range, double angleOffAxis) const {
  if (!(range > 0.0)) return false;
  if (maxRange_ > 0.0 && range > maxRange_) return false;
  if (fieldOfView_ == 0.0 || fieldOfView_ >= kTwoPi) return true;
  return angleOffAxis <= 0.5 * fieldOfView_;
}

double VisibilityLimits::uniformAssociationProbability(int visibleObjects, int detections) const {
  if (visibleObjects < 0 || detections < 0) {
    throw std::invalid_argument("visibility: negative object or detection count");
  }
  if (detections == 0) return 1.0;
  if (oneDetectionPerObject_) {
    if (detections > visibleObjects) return 0.0;
    // log(V! / (V − n)!)
    return std::exp(std::lgamma(visibleObjects - detections + 1.0) - std::lgamma(visibleObjects + 1.0));
  }
  if (visibleObjects == 0) return 0.0;
  return std::exp(-detections * std::log(static_cast<double>(visibleObjects)));
}

bool VisibilityLimits::checkAssociation(std::span<const int> beta, std::size_t objects) {
  std::vector<bool> used(objects, false);
  bool distinct = true;
  for (int b : beta) {
    if (b < 0 || static_cast<std::size_t>(b) >= objects) {
      throw std::invalid_argument("visibility: association to object " + std::to_string(b) + ", outside [0, " +
                                  std::to_string(objects) + ")");
    }
    if (used[static_cast<std::size_t>(b)]) distinct = false;
    used[static_cast<std::size_t>(b)] = true;
  }
  return distinct;
}

// ---- 2D ------------------------------------------------------------------------------------------------------

VisibilityModel2::VisibilityModel2(double fieldOfView, double maxRange, const SE2& bodyToSensor,
                                   bool oneDetectionPerObject)
    : VisibilityLimits(fieldOfView, maxRange, oneDetectionPerObject), bodyToSensor_(bodyToSensor) {}

VisibilityModel2 VisibilityModel2::fromSpec(const SensorSpec& sensor, bool oneDetectionPerObject) {
  const auto* mount = std::get_if<SE2>(&sensor.bodyToSensor);
  if (!mount) throw std::invalid_argument("VisibilityModel2: the sensor's bodyToSensor is not an SE2");
  return VisibilityModel2(sensor.fieldOfView, sensor.maxRange, *mount, oneDetectionPerObject);
}

bool VisibilityModel2::visible(const SE2& robot, const Point2& landmark) const {
  const Point2 p = (robot * bodyToSensor_).transformTo(landmark);
  return visibleAt(p.norm(), std::abs(std::atan2(p.y(), p.x())));
}

std::vector<int> VisibilityModel2::visibleObjects(const SE2& robot, std::span<const Point2> objects) const {
  std::vector<int> result;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (visible(robot, objects[i])) result.push_back(static_cast<int>(i));
  }
  return result;
}

bool VisibilityModel2::associationFeasible(const SE2& robot, std::span<const Point2> objects,
                                           std::span<const int> beta) const {
  const bool distinct = checkAssociation(beta, objects.size());
  return feasible(*this, robot, objects, beta, distinct);
}

double VisibilityModel2::associationProbability(const SE2& robot, std::span<const Point2> objects,
                                                std::span<const int> beta) const {
  if (!associationFeasible(robot, objects, beta)) return 0.0;
  return uniformAssociationProbability(static_cast<int>(visibleObjects(robot, objects).size()),
                                       static_cast<int>(beta.size()));
}

// ---- 3D ------------------------------------------------------------------------------------------------------

VisibilityModel3::VisibilityModel3(double fieldOfView, double maxRange, const SE3& bodyToSensor,
                                   bool oneDetectionPerObject)
    : VisibilityLimits(fieldOfView, maxRange, oneDetectionPerObject), bodyToSensor_(bodyToSensor) {}

VisibilityModel3 VisibilityModel3::fromSpec(const SensorSpec& sensor, bool oneDetectionPerObject) {
  const auto* mount = std::get_if<SE3>(&sensor.bodyToSensor);
  if (!mount) throw std::invalid_argument("VisibilityModel3: the sensor's bodyToSensor is not an SE3");
  return VisibilityModel3(sensor.fieldOfView, sensor.maxRange, *mount, oneDetectionPerObject);
}

bool VisibilityModel3::visible(const SE3& robot, const Point3& landmark) const {
  const Point3 p = (robot * bodyToSensor_).transformTo(landmark);
  return visibleAt(p.norm(), std::atan2(std::hypot(p.y(), p.z()), p.x()));
}

std::vector<int> VisibilityModel3::visibleObjects(const SE3& robot, std::span<const Point3> objects) const {
  std::vector<int> result;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (visible(robot, objects[i])) result.push_back(static_cast<int>(i));
  }
  return result;
}

bool VisibilityModel3::associationFeasible(const SE3& robot, std::span<const Point3> objects,
                                           std::span<const int> beta) const {
  const bool distinct = checkAssociation(beta, objects.size());
  return feasible(*this, robot, objects, beta, distinct);
}

double VisibilityModel3::associationProbability(const SE3& robot, std::span<const Point3> objects,
                                                std::span<const int> beta) const {
  if (!associationFeasible(robot, objects, beta)) return 0.0;
  return uniformAssociationProbability(static_cast<int>(visibleObjects(robot, objects).size()),
                                       static_cast<int>(beta.size()));
}

}  // namespace semslam
