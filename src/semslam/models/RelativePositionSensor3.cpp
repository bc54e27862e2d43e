#include "semslam/models/RelativePositionSensor3.h"

#include "semslam/models/PointInSensorFrame.h"

namespace semslam {

Point3 RelativePositionSensor3::predict(const SE3& robot, const Point3& point, Matrix36* Hrobot,
                                        Matrix3* Hpoint) const {
  const auto seen = pointInSensorFrame(robot, bodyToSensor_, point, Hrobot != nullptr, Hpoint != nullptr);
  if (Hrobot) *Hrobot = seen.pWrtSensor * seen.sensorWrtRobot;
  if (Hpoint) *Hpoint = seen.pWrtPoint;
  return seen.p;
}

Point3 RelativePositionSensor3::backProject(const SE3& robot, const Point3& measurement) const {
  return (robot * bodyToSensor_).transformFrom(measurement);
}

}  // namespace semslam
