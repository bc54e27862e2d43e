#pragma once
// Viewpoint: the angle θ at which an object is seen, the argument of the viewpoint-dependent classifier model
// P(z_sem | c, x, x_o) = N(h_c(θ), Σ_c(θ)) (A, eq. 2 and 18).
//
// Math
//   Paper A (sec. V) takes θ as "the relative angle from the object to camera, calculated from the relative pose
//   x_rel = x_k ⊖ x_o": the bearing of the camera's position seen from the object's frame,
//       p = x_o⁻¹ · t_x = R_oᵀ (t_x − t_o),     θ = atan2(p_y, p_x) ∈ (−π, π].
//   It depends on the camera's position only, not on its heading (a classifier sees the same side of the object
//   whichever way the camera is turned), and θ = 0 when the camera sits on the object's +x axis.
//   SE3: the same p in 3D and θ = atan2(p_y, p_x), the azimuth of the camera in the object's xy-plane (the
//   object's z axis is its "up"); the camera's height above that plane is ignored.
//   Jacobians, with respect to right perturbations of the camera pose x and of the object pose x_o
//   (translation first):
//       ∂θ/∂p = (−p_y, p_x) / ρ²,  ρ² = p_x² + p_y²,
//       ∂p/∂δx  = R_oᵀ R_x [I 0]          (only the camera's translation moves p),
//       ∂p/∂δx_o = [−I, hat(p)]           (SE2: [−I, (p_y, −p_x)ᵀ]; SE3 transformTo's Jacobian).
//   The camera pose is the pose of the sensor that classifies; with a body-to-sensor mount s, pass x · s and
//   chain with Ad(s⁻¹) (SE2::compose's first Jacobian).
//
// θ is undefined where ρ = 0 (the camera on the object's z axis, e.g. at the object itself); viewpointAngle
// throws std::domain_error there.

#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"

namespace semslam {

/// θ(x, x_o) in 2D and, where requested, ∂θ/∂δx (1x3) and ∂θ/∂δx_o (1x3).
double viewpointAngle(const SE2& camera, const SE2& object, MatrixN<1, 3>* Hcamera = nullptr,
                      MatrixN<1, 3>* Hobject = nullptr);

/// θ(x, x_o) in 3D (azimuth in the object's xy-plane) and, where requested, ∂θ/∂δx (1x6) and ∂θ/∂δx_o (1x6).
double viewpointAngle(const SE3& camera, const SE3& object, MatrixN<1, 6>* Hcamera = nullptr,
                      MatrixN<1, 6>* Hobject = nullptr);

}  // namespace semslam
