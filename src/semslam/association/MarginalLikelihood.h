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
#include <vector>

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

/// Draws X_s = X̄ ⊕ δ_s, δ_s = L n_s (L Lᵀ = Σ the marginal's covariance, n_s ~ N(0, I) the columns of one
/// standardNormalMatrix from `rng`) of a joint marginal, drawn once to be shared: every factor set evaluated on the
/// same MarginalSamples sees the same draws (common random numbers: the weights of candidates that share a parent
/// carry correlated, not independent, Monte Carlo errors, so their ratios are less noisy), and the draws' values of a
/// subset of the variables are draws of that subset's marginal, so one set of draws of x_k and the objects serves
/// every association of a hybrid component (A, eq. 17). Held as the retracted values X̄_key ⊕ (δ_s)_key of every
/// variable and draw, computed once: many factor sets read the same draws.
class MarginalSamples {
 public:
  /// Throws std::invalid_argument for samples < 2 or a marginal that does not fit `values`.
  MarginalSamples(const Values& values, const JointMarginal& marginal, int samples, std::mt19937& rng);
  int size() const { return samples_; }
  /// X̄_key ⊕ (δ_s)_key; throws std::invalid_argument for a variable the draws do not hold.
  const Value& draw(Key key, int s) const;
  bool holds(Key key) const;

 private:
  /// The position of `key` among the marginal's keys (a handful, searched in turn); throws when absent.
  std::size_t slot(Key key) const;
  int samples_ = 0;
  std::vector<Key> keys_;       // the marginal's keys in its order
  std::vector<Value> drawn_;    // variable i's draw s at i · samples + s
};

/// The per-sample log terms t_s = log P(Z | X_s) + log w(X_s) = −Σ_f logNormalizer_f − ½ Σ_f chi2_f(X_s) + log w(X_s)
/// of one factor set on shared draws (the sample handed to w holds the factors' variables only). The terms of
/// factor sets evaluated on the same draws add: the likelihood of the union of two sets of independent measurements
/// is the product of theirs at every draw, so a caller that weighs many candidates built from a few shared factor
/// sets evaluates each set once (hybrid/PropWeights.cpp). Throws std::invalid_argument when a factor names a variable
/// the draws do not hold.
Vector sampledLogTerms(std::span<const FactorPtr> factors, const MarginalSamples& samples,
                       const SampleWeight& weight = {});

/// The Monte Carlo marginal likelihood (A, eq. 16-17) over shared draws: log (1/n) Σ_s P(Z | X_s) w(X_s), the
/// log-space mean of sampledLogTerms.
SampledLikelihood sampledLikelihood(std::span<const FactorPtr> factors, const MarginalSamples& samples,
                                    const SampleWeight& weight = {});

/// The same from `samples` fresh draws of the joint marginal (MarginalSamples(values, marginal, samples, rng)).
SampledLikelihood sampledLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                    const JointMarginal& marginal, int samples, std::mt19937& rng,
                                    const SampleWeight& weight = {});

}  // namespace semslam
