#include "semslam/models/RelativePositionSensor3.h"

namespace semslam {

Point3 RelativePositionSensor3::predict(const SE3& robot, const Point3& point, Matrix36* Hrobot,
                                        Matrix3* Hpoint) const {
  Matrix6 sensorWrtRobot;
  const SE3 sensor = robot.compose(bodyToSensor_, Hrobot ? &sensorWrtRobot : nullptr, nullptr);
  Matrix36 pWrtSensor;
  const Point3 p = sensor.transformTo(point, Hrobot ? &pWrtSensor : nullptr, Hpoint);
  if (Hrobot) *Hrobot = pWrtSensor * sensorWrtRobot;
  return p;
}

Point3 RelativePositionSensor3::backProject(const SE3& robot, const Point3& measurement) const {
  return (robot * bodyToSensor_).transformFrom(measurement);
}

}  // namespace semslam
