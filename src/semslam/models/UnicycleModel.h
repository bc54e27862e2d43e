#pragma once
// UnicycleModel: a planar robot driven by a forward speed v and a turn rate ω, held constant over dt (wheel
// odometry of UTIAS Lost in the Woods and MRCLAM), integrated into an SE2 increment with its covariance.
//
// Math (right perturbation, tangent (x, y, θ), translation first)
//   With a constant body-frame twist (v, 0, ω) the pose obeys Ṫ = T · hat(v, 0, ω), whose exact solution is
//       Δ(v, ω, dt) = Exp(ξ),   ξ = (v dt, 0, ω dt)
//   (a circular arc of radius v/ω; a straight line when ω = 0). Input noise u = (v, ω) ~ N(ū, diag(σ_v², σ_ω²))
//   enters through the exact Jacobian of Δ with respect to u (Exp(ξ + dξ) = Exp(ξ) Exp(Jr(ξ) dξ)):
//       G = ∂Δ/∂u = Jr(ξ) · [dt 0; 0 0; 0 dt]                    (3x2, SE2::rightJacobian)
//       Σ = G diag(σ_v², σ_ω²) Gᵀ + dt · diag(q_x, q_y, q_θ).
//   The first term has rank ≤ 2: two inputs cannot move the pose sideways (the no-slip constraint), so its
//   Gaussian is degenerate and a factor could not whiten it. The second term, the floor, is white noise of
//   intensity q (variance per second, in the body frame at the end of the step) on every tangent direction:
//   lateral slip (q_y), and small longitudinal and heading terms that keep Σ positive definite when σ_v or σ_ω
//   is zero. Σ is positive definite for dt > 0 whenever q > 0 componentwise. The defaults (kDefaultFloor) are
//   q = (1e-6 m²/s, 1e-4 m²/s, 1e-6 rad²/s): 1 cm of lateral slip and 1 mm / 1 mrad along the other directions
//   per √s; set the floor to zero for the exact (rank-2) propagation of the input noise alone.
//
// Invariants: variances and floor intensities are finite and ≥ 0; dt is finite and ≥ 0 (dt = 0 gives the identity
// with a zero covariance); v and ω are finite. Anything else throws std::invalid_argument.

#include "semslam/geometry/SE2.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

class UnicycleModel {
 public:
  /// The default floor intensities (x, y, θ) in m²/s, m²/s, rad²/s.
  static Vector3 defaultFloor() { return Vector3(1e-6, 1e-4, 1e-6); }

  /// Input noise: σ_v² in (m/s)², σ_ω² in (rad/s)²; floor intensities q in variance per second.
  UnicycleModel(double velocityVariance, double angularVelocityVariance, const Vector3& floor = defaultFloor());

  double velocityVariance() const { return velocityVariance_; }
  double angularVelocityVariance() const { return angularVelocityVariance_; }
  const Vector3& floor() const { return floor_; }

  /// Exp((v dt, 0, ω dt)) and, where requested, G = ∂Δ/∂(v, ω) (3x2).
  static SE2 increment(double v, double omega, double dt, Matrix32* Hinput = nullptr);

  /// The increment and its covariance G diag(σ_v², σ_ω²) Gᵀ + dt diag(q), as a log's Odometry.
  Odometry integrate(double v, double omega, double dt) const;

 private:
  double velocityVariance_;
  double angularVelocityVariance_;
  Vector3 floor_;
};

}  // namespace semslam
