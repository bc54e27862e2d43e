#pragma once
// RangeBearingElevationSensor3: a 3D range, bearing and elevation sensor mounted on the robot (a stereo camera's
// triangulated detections, as in UTIAS Starry Night).
//
// The sensor's pose in the body frame is `bodyToSensor`. For a robot pose x and a world point l, with
// p = (x · s)⁻¹ l in the sensor frame and ρ = ‖(p_x, p_y)‖:
//     h(x, l) = [ ‖p‖ , atan2(p_y, p_x) , atan2(p_z, ρ) ]ᵀ
// (range in metres; bearing about the sensor's z axis in (−π, π]; elevation above its xy-plane in [−π/2, π/2]).
// Errors use difference(), which wraps both angle differences. Jacobians are with respect to right
// perturbations of x and to l. h is undefined on the sensor's z axis (ρ = 0), where the bearing is not defined;
// predict() throws std::domain_error there.

#include "semslam/geometry/SE3.h"

namespace semslam {

class RangeBearingElevationSensor3 {
 public:
  explicit RangeBearingElevationSensor3(const SE3& bodyToSensor = SE3()) : bodyToSensor_(bodyToSensor) {}

  const SE3& bodyToSensor() const { return bodyToSensor_; }

  /// h(x, l) and, where requested, ∂h/∂δx (3×6) and ∂h/∂l (3×3).
  Vector3 predict(const SE3& robot, const Point3& point, Matrix36* Hrobot = nullptr,
                  Matrix3* Hpoint = nullptr) const;

  /// measured − predicted, with both angle differences wrapped to (−π, π].
  static Vector3 difference(const Vector3& measured, const Vector3& predicted);

  /// The world point at the measured range, bearing and elevation.
  Point3 backProject(const SE3& robot, const Vector3& measurement) const;

 private:
  SE3 bodyToSensor_;
};

}  // namespace semslam
