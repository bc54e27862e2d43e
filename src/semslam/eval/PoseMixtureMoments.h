#pragma once
// PoseMixtureMoments: the Gaussian with the first two moments of a mixture of Gaussians on SE(2), the single-Gaussian
// summary of a hybrid belief's pose marginal (A, eq. 6) whose NEES says whether the mixture as a whole is consistent
// (issue 12: the heaviest component's NEES mixes "right history, consistent" with "wrong history, far off").
//
// Components (w_i, μ_i, Σ_i): weights w_i ≥ 0 (normalised here), means μ_i ∈ SE(2), Σ_i the right-perturbation
// covariance at μ_i (a draw is μ_i · Exp(e), e ~ N(0, Σ_i); geometry/SE2.h, eval/Nees.h). With m the mixture's mean
// and δ_i = Log(m⁻¹ μ_i), a draw of component i seen from m is
//     Log(m⁻¹ μ_i Exp(e)) = Log(Exp(δ_i) Exp(e)) = δ_i + Jr⁻¹(δ_i) e + O(|e|²)
// (Jr the right Jacobian of SE(2)), so to first order in the components' spread e (not in the distance between
// components, which enters exactly through δ_i):
//     m    solves Σ_i w_i Log(m⁻¹ μ_i) = 0                   (the weighted Karcher mean: the mixture's error has
//                                                            mean zero in m's tangent), by the fixed-point iteration
//                                                            m ← m · Exp(Σ_i w_i δ_i) from the heaviest mean;
//     Σ    = Σ_i w_i (Jr⁻¹(δ_i) Σ_i Jr⁻¹(δ_i)ᵀ + δ_i δ_iᵀ)  (the within- and between-component parts).
// One component gives (μ_1, Σ_1) exactly.
//
// Throws std::invalid_argument for empty or mismatched input, a negative, non-finite or all-zero weight, or an
// iteration that does not converge (|Σ w_i δ_i| > 1e-10 after 100 steps: components spread over more than a half
// turn, where the Karcher mean is not unique).

#include <vector>

#include "semslam/geometry/Matrix.h"
#include "semslam/geometry/SE2.h"

namespace semslam {

struct PoseGaussian2 {
  SE2 mean;
  Matrix3 covariance;
};

PoseGaussian2 momentMatchedPoseMixture(const std::vector<double>& weights, const std::vector<SE2>& means,
                                       const std::vector<Matrix3>& covariances);

}  // namespace semslam
