#include "semslam/models/RangeBearingElevationSensor3.h"

#include <cmath>
#include <stdexcept>

#include "semslam/models/Angle.h"
#include "semslam/models/PointInSensorFrame.h"

namespace semslam {

Vector3 RangeBearingElevationSensor3::predict(const SE3& robot, const Point3& point, Matrix36* Hrobot,
                                              Matrix3* Hpoint) const {
  const auto seen = pointInSensorFrame(robot, bodyToSensor_, point, Hrobot != nullptr, Hpoint != nullptr);
  const Point3& p = seen.p;
  const double planarSquared = p.x() * p.x() + p.y() * p.y();
  if (planarSquared == 0.0) throw std::domain_error("range-bearing-elevation: the point is on the sensor's z axis");
  const double planar = std::sqrt(planarSquared);
  const double squaredRange = planarSquared + p.z() * p.z();
  const double range = std::sqrt(squaredRange);
  // Rows: ∂range/∂p = pᵀ/r; ∂bearing/∂p = (−p_y, p_x, 0)/ρ²; ∂elevation/∂p = (−p_x p_z, −p_y p_z, ρ²)/(ρ r²).
  Matrix3 hWrtP;
  hWrtP << p.x() / range, p.y() / range, p.z() / range,  //
      -p.y() / planarSquared, p.x() / planarSquared, 0.0,  //
      -p.x() * p.z() / (planar * squaredRange), -p.y() * p.z() / (planar * squaredRange), planar / squaredRange;
  if (Hrobot) *Hrobot = hWrtP * seen.pWrtSensor * seen.sensorWrtRobot;
  if (Hpoint) *Hpoint = hWrtP * seen.pWrtPoint;
  return Vector3(range, std::atan2(p.y(), p.x()), std::atan2(p.z(), planar));
}

Vector3 RangeBearingElevationSensor3::difference(const Vector3& measured, const Vector3& predicted) {
  return Vector3(measured(0) - predicted(0), wrapAngle(measured(1) - predicted(1)),
                 wrapAngle(measured(2) - predicted(2)));
}

Point3 RangeBearingElevationSensor3::backProject(const SE3& robot, const Vector3& measurement) const {
  const double range = measurement(0), bearing = measurement(1), elevation = measurement(2);
  const Point3 inSensor(range * std::cos(elevation) * std::cos(bearing),
                        range * std::cos(elevation) * std::sin(bearing), range * std::sin(elevation));
  return (robot * bodyToSensor_).transformFrom(inSensor);
}

}  // namespace semslam
