#pragma once
// A point seen from a sensor mounted on a robot, the first step of every point sensor model (RelativePosition*,
// RangeBearing*):
//   sensor = robot · bodyToSensor,   p = sensor⁻¹ · point
// with the factors of its Jacobians (right perturbations; the mount is fixed):
//   ∂p/∂robot = pWrtSensor · sensorWrtRobot,   ∂p/∂point = pWrtPoint.
// A sensor model chains its own ∂h/∂p in front, h ∘ p, keeping the product order hWrtP · pWrtSensor · sensorWrtRobot.
// The Jacobian factors are computed only when asked for (withRobotJacobian, withPointJacobian).

#include "semslam/geometry/Matrix.h"

namespace semslam {

template <class PoseType, class Point>
struct PointInSensorFrame {
  static constexpr int kPointDim = static_cast<int>(Point::RowsAtCompileTime);
  Point p;
  MatrixN<kPointDim, PoseType::kDim> pWrtSensor;
  MatrixN<PoseType::kDim, PoseType::kDim> sensorWrtRobot;
  MatrixN<kPointDim, kPointDim> pWrtPoint;
};

template <class PoseType, class Point>
PointInSensorFrame<PoseType, Point> pointInSensorFrame(const PoseType& robot, const PoseType& bodyToSensor,
                                                        const Point& point, bool withRobotJacobian,
                                                        bool withPointJacobian) {
  PointInSensorFrame<PoseType, Point> seen;
  const PoseType sensor = robot.compose(bodyToSensor, withRobotJacobian ? &seen.sensorWrtRobot : nullptr, nullptr);
  seen.p = sensor.transformTo(point, withRobotJacobian ? &seen.pWrtSensor : nullptr,
                              withPointJacobian ? &seen.pWrtPoint : nullptr);
  return seen;
}

}  // namespace semslam
