#pragma once
// The marginal likelihood p(z | H) = ∫ p(z | X) N(X; X̄, Σ) dX (A, eq. 16-17) by importance sampling from the
// linearised posterior, for broad priors under which plain Monte Carlo (sampledLikelihood) puts almost no sample
// where p(z | X) is non-negligible.
//
// Math (the conventions of MarginalLikelihood.h: tangent δ at X̄, X = X̄ ⊕ δ, δ ~ N(0, Σ) in the marginal's key
// order; stacked whitened error r(X̄ ⊕ δ) ≈ r̄ + J δ at the mean):
//   proposal   the Laplace approximation of p(δ | z) ∝ p(z | X̄ ⊕ δ) N(δ; 0, Σ) linearised at the mean (the
//              linearised / Kalman update):
//                  Σ' = (Σ⁻¹ + JᵀJ)⁻¹ = Σ − K J Σ,   δ' = −Σ' Jᵀ r̄ = −K r̄,   K = Σ Jᵀ S⁻¹,  S = J Σ Jᵀ + I,
//                  log det Σ' = log det Σ − log det S   (matrix determinant lemma);
//   draws      δ_s = δ' + L' n_s, L' L'ᵀ = Σ', n_s ~ N(0, I) (models/Sampling.h: same seed, same draws);
//   weights    ω_s = p(z | X_s) N(δ_s; 0, Σ) / N(δ_s; δ', Σ') · w(X_s), with w the optional per-sample weight
//              (the visibility model P(β | x, X^o), A eq. 16); in logs
//                  log ω_s = Σ_f (−½ chi2_f(X_s) − logNormalizer_f) − ½ |L⁻¹ δ_s|² + ½ |n_s|² − ½ log det S + log w,
//              with L Lᵀ = Σ (the 2π terms cancel);
//   estimate   p(z | H) ≈ (1/n) Σ_s ω_s, unbiased for any proposal whose support covers the integrand's; its
//              relative standard error is sd(ω) / (√n · mean ω), as SampledLikelihood's.
// Iterated proposal (ImportanceProposal::iterations > 1): the update is repeated with r and J relinearised at
// X̄ ⊕ δ'_i, r(δ) ≈ r_i + J_i (δ − δ'_i), giving δ'_{i+1} = −K_i (r_i − J_i δ'_i), Σ'_{i+1} = Σ − K_i J_i Σ (the
// iterated Kalman update, a Gauss-Newton step on φ(δ) = ½|r(X̄ ⊕ δ)|² + ½ δᵀΣ⁻¹δ toward the posterior mode, i.e.
// the Laplace approximation proper); an iterate is kept only while φ at its mean decreases. The log weights
// above hold with S = S_i of the kept iterate. Any proposal gives an unbiased estimate; iterating only moves
// it closer to the posterior when the mean is far from the measurement's support.
// For a linear-Gaussian model p(z | X) N(δ; 0, Σ) = p(z) N(δ; δ', Σ') exactly, so every ω_s = p(z) (w ≡ 1) and
// the estimate is exact with zero variance. For nonlinear factors the proposal is only as good as the
// linearisation at X̄; the relative standard error reports how good.
//
// Invariants (else std::invalid_argument): samples ≥ 2; iterations ≥ 1; Σ positive definite; every factor a normalised Gaussian
// density; every key of every factor in `marginal` and in `values`; per-sample weights finite and ≥ 0.

#include <random>
#include <span>

#include "semslam/association/MarginalLikelihood.h"

namespace semslam {

struct ImportanceProposal {
  int iterations = 1;  ///< linearisations of the update: 1 at the mean (the linearised update), > 1 iterated
};

/// The importance-sampled marginal likelihood with the linearised posterior as proposal (A, eq. 16-17).
SampledLikelihood importanceSampledLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                              const JointMarginal& marginal, int samples, std::mt19937& rng,
                                              const SampleWeight& weight = {},
                                              const ImportanceProposal& proposal = {});

}  // namespace semslam
