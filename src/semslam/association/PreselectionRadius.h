#pragma once
// PreselectionRadius: the ball around a detection's back-projection that holds every landmark able to pass the
// association gate (docs/association-front-end.md, §7, which has the derivation).
//
// Math. Let b be the detection's back-projection from the pose estimate x̄ (position t, heading/rotation), l̄ a
// landmark's position estimate, D = ‖l̄ − b‖, and the gate accept d² = r̄ᵀ S⁻¹ r̄ ≤ T (S = H Σ_joint Hᵀ + R,
// MarginalLikelihood.h; T the gate's χ²_m quantile plus any semantic allowance, below). With
//   σ_t = √λmax(Σ_x translation block),  σ_φ = √λmax(Σ_x rotation block),  σ_l ≥ √λmax(Σ_l position block),
//   ℓ = ‖b − t‖ (lever arm from the body origin),  r the measured range (from the sensor),
// every landmark that passes satisfies
//     D ≤ k √T (σ_t + σ_φ (ℓ + D) + σ_l + σ_0 + σ_a (r + D)),
// hence, when κ = k √T (σ_φ + σ_a) < 1,
//     D ≤ base + slope · σ_l,   base = k √T (σ_t + σ_φ ℓ + σ_0 + σ_a r) / (1 − κ),   slope = k √T / (1 − κ),
// with, per sensor: range-bearing(-elevation) k = √m, σ_0 = √R_rr, σ_a = √(Σ angular variances); relative
// position k = 1, σ_0 = √λmax(R), σ_a = 0. When κ ≥ 1 the gate bounds no distance (the linearised uncertainty grows
// with range as fast as the range): no ball. Relative-pose sensors (an SE(n) log residual) have no ball either.
//
// Joint gate (BirthRule::Unassigned): g = d² − 2 ln(P(s | j) / P₀(s)) ≤ T_χ², and P(s | j) ≤ max_c P(s | c), so a
// landmark that passes has d² ≤ T_χ² + semanticGateAllowance(s).

#include <optional>

#include "semslam/association/MeasurementFactory.h"
#include "semslam/graph/Values.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// The landmarks that can pass: those with ‖l̄_j − center‖ ≤ base + slope · σ_l,j.
struct PreselectionBall {
  Vector center;  ///< the back-projection b (2 or 3 coordinates)
  double base = 0.0;
  double slope = 0.0;
};

/// 2 ln(max_c P(s | c) / P₀(s)) ≥ 0, P₀(s) = the mean likelihood (the uniform class prior's predictive), as the
/// joint gate defines it; 0 when the label carries no usable information (no classes, or all likelihoods 0).
double semanticGateAllowance(const Vector& likelihoods);

/// √λmax of the position block (the first `dimension` rows and columns) of a landmark's tangent covariance.
double positionSpread(const Matrix& covariance, int dimension);

/// The residual dimension m of the sensor's detection factor (the gate's degrees of freedom).
int gateDegreesOfFreedom(const SensorSpec& sensor, int dimension);

/// The ball of the class comment for `detection` from `pose` (a Value: SE2 or SE3) with tangent covariance
/// `poseCovariance`, under a gate threshold `threshold` (T). nullopt: no finite ball (see above).
std::optional<PreselectionBall> preselectionBall(const MeasurementFactory& factory, const SensorSpec& sensor,
                                                 const Value& pose, const Matrix& poseCovariance,
                                                 const Detection& detection, double threshold);

}  // namespace semslam
