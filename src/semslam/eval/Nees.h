#pragma once
// Consistency: the normalised estimation error squared (NEES; Bar-Shalom, Li, Kirubarajan, "Estimation with
// Applications to Tracking and Navigation", 2001, sec. 5.4) of estimates that come with a covariance.
//
// Convention (semslam's right perturbation, geometry/SE2.h and SE3.h): an estimate T̂ with covariance Σ states
// that the truth is T = T̂ · Exp(e) with e ~ N(0, Σ), e in the tangent at T̂, translation first. Hence
//   e = Log(T̂⁻¹ T)                       (the truth seen from the estimate; SE2: (x, y, θ), SE3: (ρ, φ))
//   NEES = eᵀ Σ⁻¹ e                        (dimensionless; χ²_d distributed when the estimate is consistent)
// For points (landmark positions) e = p − p̂. The sign of e does not change the NEES, but the side does: the left
// error Log(T T̂⁻¹) = Ad_T̂ e would need Σ transported by the adjoint, so Σ must be the right-perturbation
// covariance of the estimate, which is what the solvers' marginals (solve/JointMarginal.h) are.
//
// Over n NEES values of dimension d, the average NEES ε̄ = (1/n) Σ ε_i satisfies n ε̄ ~ χ²_{n d} when the errors
// are independent and the estimates consistent, so the two-sided band with confidence 1 − α is
//   [ F⁻¹_{nd}(α/2) / n,  F⁻¹_{nd}(1 − α/2) / n ]        (95 %: α = 0.05)
// and ε̄ should lie in it (above: over-confident, below: conservative). Poses along one trajectory are correlated,
// so for them the band is a guide, not an exact test.
//
// Throws InputError for mismatched dimensions, non-finite input, or a covariance that is not symmetric positive
// definite (Cholesky fails).

#include <cstddef>
#include <limits>
#include <vector>

#include "semslam/geometry/Matrix.h"
#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"

namespace semslam {

/// eᵀ Σ⁻¹ e (by a Cholesky factorisation of Σ).
double normalizedErrorSquared(const Vector& error, const Matrix& covariance);

/// e = Log(estimate⁻¹ truth), the right-perturbation error.
Vector3 poseError(const SE2& estimate, const SE2& truth);
Vector6 poseError(const SE3& estimate, const SE3& truth);

/// NEES of a pose estimate with its right-perturbation covariance (3x3 for SE2, 6x6 for SE3).
double poseNees(const SE2& estimate, const SE2& truth, const Matrix& covariance);
double poseNees(const SE3& estimate, const SE3& truth, const Matrix& covariance);
/// NEES of a point estimate: e = truth − estimate.
double pointNees(const Vector& estimate, const Vector& truth, const Matrix& covariance);

struct NeesSummary {
  double mean = std::numeric_limits<double>::quiet_NaN();   ///< ε̄; NaN when there is no value
  std::size_t count = 0;                                    ///< n
  int dimension = 0;                                        ///< d
  double confidence = 0.95;                                 ///< 1 − α
  double lower = std::numeric_limits<double>::quiet_NaN();  ///< F⁻¹_{nd}(α/2) / n
  double upper = std::numeric_limits<double>::quiet_NaN();  ///< F⁻¹_{nd}(1 − α/2) / n
  bool withinBand() const { return mean >= lower && mean <= upper; }
};

/// ε̄ and its band for `values` of dimension `dimension` (≥ 1); confidence in (0, 1). Empty values give NaNs.
NeesSummary summarizeNees(const std::vector<double>& values, int dimension, double confidence = 0.95);

}  // namespace semslam
