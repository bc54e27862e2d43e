#pragma once
// RelativePositionSensor2: a planar sensor mounted on the robot that measures a point's position in its own frame
// (a landmark detector giving (x, y), g2o EDGE_SE2_XY, iSAM LANDMARK with a mount).
//
// The sensor's pose in the body frame is `bodyToSensor` (an offset along the body x axis is SE2(d, 0, 0)).
// For a robot pose x and a world point l:
//     h(x, l) = (x · s)⁻¹ l = R_sᵀ (R_xᵀ (l − t_x) − t_s)        (metres, in the sensor frame)
// Errors are plain differences (difference() = measured − predicted). Jacobians are with respect to right
// perturbations of x (2x3, translation first) and to l (2x2):
//     ∂h/∂δx = ∂((x s)⁻¹ l)/∂δ_{xs} · Ad(s⁻¹),   ∂h/∂l = (R_x R_s)ᵀ.
// h is defined everywhere.

#include "semslam/geometry/SE2.h"

namespace semslam {

class RelativePositionSensor2 {
 public:
  explicit RelativePositionSensor2(const SE2& bodyToSensor = SE2()) : bodyToSensor_(bodyToSensor) {}

  const SE2& bodyToSensor() const { return bodyToSensor_; }

  /// h(x, l) and, where requested, ∂h/∂δx (2x3) and ∂h/∂l (2x2).
  Point2 predict(const SE2& robot, const Point2& point, Matrix23* Hrobot = nullptr, Matrix2* Hpoint = nullptr) const;

  /// measured − predicted.
  static Vector2 difference(const Vector2& measured, const Vector2& predicted) { return measured - predicted; }

  /// The world point at the measured sensor-frame position (the inverse of h for a known robot pose).
  Point2 backProject(const SE2& robot, const Point2& measurement) const;

 private:
  SE2 bodyToSensor_;
};

}  // namespace semslam
