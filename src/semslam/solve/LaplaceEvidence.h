#pragma once
// LaplaceEvidence: −2 ln of a factor graph's evidence, the probability of its measurements with every variable
// integrated out, p(Z) = ∫ Π_f p_f(z_f | X) dX, by Laplace's approximation at a mode X̂ (MacKay, "Information
// Theory, Inference, and Learning Algorithms", ch. 27):
//
//   −2 ln p(Z) ≈ Σ_f [chi2_f(X̂) + 2 n_f] + ln det Λ(X̂) − N ln 2π,
//
// with n_f each factor's logNormalizer (graph/Factor.h: p_f = exp(−½ chi2_f − n_f)), Λ = Σ_f J_fᵀ J_f the
// Gauss-Newton information at X̂ (NormalEquations.h) and N its dimension, the tangent dimensions of the variables
// the factors touch (a variable no factor touches is not integrated). The variables carry no prior of their own:
// the integral is over a flat one of density 1 per unit of tangent volume, so a caller whose model has a proper
// prior density ρ on a variable that no factor here states adds −2 ln ρ for it.
//
// Exact where the factors are linear in X (the integral of a Gaussian); otherwise the second-order approximation
// about X̂, which must be a mode (a converged estimate) for the linear term to vanish.
//
// Throws std::invalid_argument for a factor that is not a normalised Gaussian (no logNormalizer: robust kernels,
// mixtures; pass a mixture's active component) and std::domain_error when Λ is not positive definite (some
// variable the factors do not determine: its integral diverges).

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"

namespace semslam {

/// −2 ln p(Z) as above, for `graph` at its mode `mode`.
double laplaceEvidenceScore(const FactorGraph& graph, const Values& mode);

}  // namespace semslam
