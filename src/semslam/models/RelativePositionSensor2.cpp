#include "semslam/models/RelativePositionSensor2.h"

#include "semslam/models/PointInSensorFrame.h"

namespace semslam {

Point2 RelativePositionSensor2::predict(const SE2& robot, const Point2& point, Matrix23* Hrobot,
                                        Matrix2* Hpoint) const {
  const auto seen = pointInSensorFrame(robot, bodyToSensor_, point, Hrobot != nullptr, Hpoint != nullptr);
  if (Hrobot) *Hrobot = seen.pWrtSensor * seen.sensorWrtRobot;
  if (Hpoint) *Hpoint = seen.pWrtPoint;
  return seen.p;
}

Point2 RelativePositionSensor2::backProject(const SE2& robot, const Point2& measurement) const {
  return (robot * bodyToSensor_).transformFrom(measurement);
}

}  // namespace semslam
