#pragma once
// VelocityModel3: a 3D body moving with a body-frame linear velocity v and angular velocity ω, held constant over
// dt (the velocity sensor of UTIAS Starry Night), integrated into an SE3 increment with its covariance.
//
// Math (right perturbation, tangent (ρ, φ), translation first)
//   A constant body-frame twist u = (v, ω) gives Ṫ = T · hat(u), whose exact solution is
//       Δ(v, ω, dt) = Exp(ξ),   ξ = dt · (v, ω)
//   (a screw motion; the translation is V(φ) ρ, not v dt, when ω ≠ 0). The input u ~ N(ū, Σ_u) with Σ_u 6x6 in
//   the order (v, ω) — translation first, like the tangent: Starry Night lists (ω, v), reorder it — propagates
//   through the exact Jacobian (Exp(ξ + dξ) = Exp(ξ) Exp(Jr(ξ) dξ)):
//       G = ∂Δ/∂u = dt · Jr(ξ)                                  (6x6, SE3::rightJacobian)
//       Σ = G Σ_u Gᵀ + dt · diag(q),
//   with an optional floor of white-noise intensities q (variance per second, default zero). G is invertible for
//   dt > 0 and |ω dt| < 2π, so Σ is positive definite when Σ_u is; the floor is there for inputs that are not
//   all noisy (a Σ_u of rank < 6).
//
// Invariants: Σ_u is finite, symmetric and positive semi-definite; q ≥ 0; dt finite and ≥ 0 (dt = 0 gives the
// identity with a zero covariance); v, ω finite. Anything else throws std::invalid_argument.

#include "semslam/geometry/SE3.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

class VelocityModel3 {
 public:
  /// Σ_u: covariance of (v, ω) (6x6, translation first); floor: intensities q, variance per second.
  explicit VelocityModel3(const Matrix6& inputCovariance, const Vector6& floor = Vector6::Zero());
  /// Independent inputs: variances of (v_x, v_y, v_z) and of (ω_x, ω_y, ω_z).
  VelocityModel3(const Vector3& velocityVariances, const Vector3& angularVelocityVariances,
                 const Vector6& floor = Vector6::Zero());

  const Matrix6& inputCovariance() const { return inputCovariance_; }
  const Vector6& floor() const { return floor_; }

  /// Exp(dt (v, ω)) and, where requested, G = ∂Δ/∂(v, ω) = dt Jr(ξ) (6x6).
  static SE3 increment(const Vector3& v, const Vector3& omega, double dt, Matrix6* Hinput = nullptr);

  /// The increment and its covariance G Σ_u Gᵀ + dt diag(q), as a log's Odometry.
  Odometry integrate(const Vector3& v, const Vector3& omega, double dt) const;

 private:
  Matrix6 inputCovariance_;
  Vector6 floor_;
};

}  // namespace semslam
