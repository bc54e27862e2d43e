#pragma once
// Odometry composition: chaining two odometry increments, with their covariances, into one (for keyframing: the
// motion between two keyframes is the composition of the per-step increments between them).
//
// Math (first order, right perturbation, translation-first tangent as everywhere in semslam)
//   An increment a with covariance Σ_a means a_true = a · Exp(δ_a), δ_a ~ N(0, Σ_a); likewise b, and δ_a, δ_b are
//   independent. Their composition c = a · b is then
//       a Exp(δ_a) b Exp(δ_b) = a b Exp(Ad(b⁻¹) δ_a) Exp(δ_b) ≈ c · Exp(Ad(b⁻¹) δ_a + δ_b),
//   so to first order
//       Σ_c = Ad(b⁻¹) Σ_a Ad(b⁻¹)ᵀ + Σ_b,
//   with Ad(b⁻¹) = ∂(a·b)/∂δ_a, the compose() Jacobian of SE2/SE3. The neglected terms are O(|δ|³) in the
//   covariance (tested against Monte Carlo in tests/models/testOdometry.cpp).
//
// Invariants: both increments are SE2 (3x3 covariances) or both SE3 (6x6); covariances are finite and symmetric
// (positive semi-definite: a zero covariance is allowed, e.g. identityOdometry()). Anything else throws
// std::invalid_argument naming the problem. Composition is associative (up to the first-order approximation of
// the covariance) and identityOdometry(d) is its neutral element.

#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// The identity increment with a zero covariance, in dimension 2 (SE2) or 3 (SE3): the start of an accumulation.
Odometry identityOdometry(int dimension);

/// first · second with Σ = Ad(second⁻¹) Σ_first Ad(second⁻¹)ᵀ + Σ_second.
Odometry composeOdometry(const Odometry& first, const Odometry& second);

/// Throws std::invalid_argument unless `odometry` is SE2 with a 3x3 or SE3 with a 6x6 finite symmetric covariance.
void checkOdometry(const Odometry& odometry);

}  // namespace semslam
