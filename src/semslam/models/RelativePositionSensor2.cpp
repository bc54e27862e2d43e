#include "semslam/models/RelativePositionSensor2.h"

namespace semslam {

Point2 RelativePositionSensor2::predict(const SE2& robot, const Point2& point, Matrix23* Hrobot,
                                        Matrix2* Hpoint) const {
  Matrix3 sensorWrtRobot;
  const SE2 sensor = robot.compose(bodyToSensor_, Hrobot ? &sensorWrtRobot : nullptr, nullptr);
  Matrix23 pWrtSensor;
  const Point2 p = sensor.transformTo(point, Hrobot ? &pWrtSensor : nullptr, Hpoint);
  if (Hrobot) *Hrobot = pWrtSensor * sensorWrtRobot;
  return p;
}

Point2 RelativePositionSensor2::backProject(const SE2& robot, const Point2& measurement) const {
  return (robot * bodyToSensor_).transformFrom(measurement);
}

}  // namespace semslam
