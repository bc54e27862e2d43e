#pragma once
// The marginal likelihood of a measurement under a Gaussian belief over the variables it involves: the one
// component likelihood both methods need.
//
//   Paper B (sec. IV-B): the weight of associating detection z with landmark l is proportional to
//       p(z | H) = ∫ p(z | x, l) N([x; l]; [x̄; l̄], Σ_joint) d[x; l]
//   Paper A (eq. 15-17): the weight of a component's association β_k is the same integral over the joint marginal
//   of the current pose and the associated objects, of the geometric and semantic likelihoods (eq. 10), times the
//   visibility model; the paper draws samples, we also offer the linearised closed form.
//
// Math. Let the measurement's factors be stacked into one whitened error r(X) = R (z ⊖ h(X)) (each factor whitens
// with its own R; dimension m) linearised at the estimate X̄:  r(X̄ ⊕ δ) ≈ r̄ + J δ, with δ ~ N(0, Σ) the joint
// marginal of the factors' variables (tangent at X̄, in JointMarginal's key order). Then
//       p(z | H) ≈ |R| N(r̄; 0, S),   S = J Σ Jᵀ + I,
//       log p = −½ r̄ᵀ S⁻¹ r̄ − ½ log det(2π S) + log|R|
//             = −½ r̄ᵀ S⁻¹ r̄ − ½ log det S − Σ_f logNormalizer_f,
// which in unwhitened terms is log N(z; h(X̄), H Σ Hᵀ + Σ_z) (B, sec. IV-B). It is exact for linear models.
// The innovation chi2 r̄ᵀ S⁻¹ r̄ is χ²_m-distributed for a correct association: the gate tests it.
//
// Sampling (A, eq. 17): p(z | H) ≈ (1/n) Σ_s w(X_s) Π_f exp(−½ chi2_f(X_s) − logNormalizer_f),
// X_s = X̄ ⊕ δ_s, δ_s ~ N(0, Σ) drawn through the Cholesky factor of Σ (Sampling.h: same seed, same draws);
// w is an optional per-sample weight (the visibility model P(β | x, X^o), eq. 16). Averages are taken in log
// space (log-sum-exp), so likelihoods far below the smallest double are still ordered correctly.
//
// Every factor must be a normalised Gaussian density (Factor::logNormalizer() present), and every key of every
// factor must be in `marginal` and in `values`; otherwise std::invalid_argument.

#include <functional>
#include <random>
#include <span>

#include "semslam/graph/Factor.h"
#include "semslam/graph/Values.h"
#include "semslam/solve/JointMarginal.h"

namespace semslam {

struct LinearizedLikelihood {
  double logLikelihood = 0.0;  ///< log p(z | H), linearised
  double innovationChi2 = 0.0; ///< r̄ᵀ S⁻¹ r̄
  int dimension = 0;           ///< m, the stacked measurement dimension (the gate's degrees of freedom)
};

/// The linearised marginal likelihood of the stacked `factors` at `values` under `marginal`.
LinearizedLikelihood linearizedLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                          const JointMarginal& marginal);

struct SampledLikelihood {
  double logLikelihood = 0.0;        ///< log of the Monte Carlo mean
  double relativeStandardError = 0.0;///< standard error of the mean over the mean (its Monte Carlo error)
  int samples = 0;
};

/// Per-sample weight w(X_s) ≥ 0 (e.g. the visibility model); empty: w ≡ 1.
using SampleWeight = std::function<double(const Values& sample)>;

/// The Monte Carlo marginal likelihood (A, eq. 17) from `samples` draws of the joint marginal.
SampledLikelihood sampledLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                    const JointMarginal& marginal, int samples, std::mt19937& rng,
                                    const SampleWeight& weight = {});

}  // namespace semslam
