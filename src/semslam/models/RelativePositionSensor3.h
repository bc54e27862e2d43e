#pragma once
// RelativePositionSensor3: a 3D sensor mounted on the robot that measures a point's position in its own frame
// (a stereo or depth camera's triangulated detection).
//
// The sensor's pose in the body frame is `bodyToSensor`. For a robot pose x and a world point l:
//     h(x, l) = (x · s)⁻¹ l                                    (metres, in the sensor frame)
// Errors are plain differences (difference() = measured − predicted). Jacobians are with respect to right
// perturbations of x (3x6, translation first) and to l (3x3):
//     ∂h/∂δx = [−I, p^] · Ad(s⁻¹)  (p = h(x, l)),   ∂h/∂l = (R_x R_s)ᵀ.
// h is defined everywhere.

#include "semslam/geometry/SE3.h"

namespace semslam {

class RelativePositionSensor3 {
 public:
  explicit RelativePositionSensor3(const SE3& bodyToSensor = SE3()) : bodyToSensor_(bodyToSensor) {}

  const SE3& bodyToSensor() const { return bodyToSensor_; }

  /// h(x, l) and, where requested, ∂h/∂δx (3x6) and ∂h/∂l (3x3).
  Point3 predict(const SE3& robot, const Point3& point, Matrix36* Hrobot = nullptr, Matrix3* Hpoint = nullptr) const;

  /// measured − predicted.
  static Vector3 difference(const Vector3& measured, const Vector3& predicted) { return measured - predicted; }

  /// The world point at the measured sensor-frame position (the inverse of h for a known robot pose).
  Point3 backProject(const SE3& robot, const Point3& measurement) const;

 private:
  SE3 bodyToSensor_;
};

}  // namespace semslam
