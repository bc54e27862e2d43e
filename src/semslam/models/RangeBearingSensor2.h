#pragma once
// RangeBearingSensor2: a planar range-bearing sensor mounted on the robot.
//
// The sensor's pose in the body frame is `bodyToSensor` (an offset along the body x axis is SE2(d, 0, 0)).
// For a robot pose x and a point l (world frame), with the point in the sensor frame p = (x · s)⁻¹ l:
//     h(x, l) = [ ‖p‖ , atan2(p_y, p_x) ]ᵀ       (range in metres, bearing in radians in (−π, π]).
// Measurement errors are taken with difference(): bearing differences are wrapped to (−π, π], so the error is
// continuous across the ±π seam. Jacobians are with respect to right perturbations of x and to l.
// h is undefined at p = 0 (the point at the sensor); predict() throws std::domain_error there.

#include "semslam/geometry/SE2.h"

namespace semslam {

class RangeBearingSensor2 {
 public:
  explicit RangeBearingSensor2(const SE2& bodyToSensor = SE2()) : bodyToSensor_(bodyToSensor) {}

  const SE2& bodyToSensor() const { return bodyToSensor_; }

  /// h(x, l) and, where requested, ∂h/∂δx (2×3) and ∂h/∂l (2×2).
  Vector2 predict(const SE2& robot, const Point2& point, Matrix23* Hrobot = nullptr, Matrix2* Hpoint = nullptr) const;

  /// measured − predicted, with the bearing difference wrapped to (−π, π].
  static Vector2 difference(const Vector2& measured, const Vector2& predicted);

  /// The world point at the measured range and bearing (the inverse of h for a known robot pose).
  Point2 backProject(const SE2& robot, const Vector2& measurement) const;

 private:
  SE2 bodyToSensor_;
};

}  // namespace semslam
