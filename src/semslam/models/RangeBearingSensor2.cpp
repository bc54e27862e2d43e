#include "semslam/models/RangeBearingSensor2.h"

#include <cmath>
#include <stdexcept>

#include "semslam/models/Angle.h"
#include "semslam/models/PointInSensorFrame.h"

namespace semslam {

Vector2 RangeBearingSensor2::predict(const SE2& robot, const Point2& point, Matrix23* Hrobot,
                                     Matrix2* Hpoint) const {
  const auto seen = pointInSensorFrame(robot, bodyToSensor_, point, Hrobot != nullptr, Hpoint != nullptr);
  const Point2& p = seen.p;
  const double squaredRange = p.squaredNorm();
  if (squaredRange == 0.0) throw std::domain_error("range-bearing: the point is at the sensor");
  const double range = std::sqrt(squaredRange);
  // ∂(range, bearing)/∂p = [ pᵀ/r ; (−p_y, p_x)/r² ].
  Matrix2 hWrtP;
  hWrtP << p.x() / range, p.y() / range, -p.y() / squaredRange, p.x() / squaredRange;
  if (Hrobot) *Hrobot = hWrtP * seen.pWrtSensor * seen.sensorWrtRobot;
  if (Hpoint) *Hpoint = hWrtP * seen.pWrtPoint;
  return Vector2(range, std::atan2(p.y(), p.x()));
}

Vector2 RangeBearingSensor2::difference(const Vector2& measured, const Vector2& predicted) {
  return Vector2(measured(0) - predicted(0), wrapAngle(measured(1) - predicted(1)));
}

Point2 RangeBearingSensor2::backProject(const SE2& robot, const Vector2& measurement) const {
  const Point2 inSensor(measurement(0) * std::cos(measurement(1)), measurement(0) * std::sin(measurement(1)));
  return (robot * bodyToSensor_).transformFrom(inSensor);
}

}  // namespace semslam
