#pragma once
// Factor: one term of the nonlinear least-squares objective  F(X) = ½ Σ_f chi2_f(X).
//
// A factor touches the variables named by keys() and gives, at a linearization point X,
//   r(X)   its whitened error (dimension errorDimension()): ‖r‖² is its chi2 (ρ(‖r‖²) with a robust kernel, whose
//          IRLS weight is folded into r and J),
//   J_k    ∂r/∂δ_k for each key k, with respect to the right perturbation X_k ⊕ δ_k (translation-first tangent).
//
// Factors are immutable once built and shared through FactorPtr (std::shared_ptr<const Factor>), so factor
// graphs, smoothers and the branching hypotheses of the hybrid belief share them instead of copying them.

#include <memory>
#include <optional>
#include <vector>

#include "semslam/geometry/Matrix.h"
#include "semslam/graph/Key.h"
#include "semslam/graph/Values.h"

namespace semslam {

/// A factor linearized at one point: whitened error, one whitened Jacobian per key in keys() order, and the
/// factor's chi2 there (which differs from ‖whitenedError‖² only under a robust kernel). The solvers keep one per
/// factor and reuse it across iterations, so its storage is allocated once.
struct LinearizedFactor {
  Vector whitenedError;
  std::vector<Matrix> jacobians;
  double chi2 = 0.0;
};

class Factor {
 public:
  explicit Factor(std::vector<Key> keys) : keys_(std::move(keys)) {}
  virtual ~Factor() = default;
  Factor(const Factor&) = delete;
  Factor& operator=(const Factor&) = delete;

  const std::vector<Key>& keys() const { return keys_; }
  virtual int errorDimension() const = 0;

  /// Whitened error and Jacobians at `values` (see the class comment); resizes `out` as needed.
  virtual void linearize(const Values& values, LinearizedFactor& out) const = 0;

  /// The factor's chi2 at `values`: ‖r‖², or ρ(‖r‖²) with a robust kernel.
  virtual double chi2(const Values& values) const = 0;

  /// For a factor that is a Gaussian density of its measurement, p(z | X) = exp(−½ chi2(X) − logNormalizer())
  /// with logNormalizer = ½ d log 2π − log|R| (graph/NoiseModel.h). Factors that are not a normalised Gaussian
  /// density (robust kernels, mixtures) return std::nullopt; marginal likelihoods and mixture weights need it.
  virtual std::optional<double> logNormalizer() const { return std::nullopt; }

  /// For a factor with a discrete choice (a max-mixture, factors/MaxMixtureFactor.h): the index of the component
  /// linearize() would use at `values`. −1 for a factor without one. The smoothers use it to re-choose components
  /// at a new estimate (docs/incremental-smoother.md, "Mixtures").
  virtual int activeComponent(const Values& /*values*/) const { return -1; }

  /// For a detection factor, whose error depends on its variables (keys() = {robot pose x, landmark l}) only through
  /// p = x⁻¹ · l, the landmark's position as the robot sees it: a bound δ ≥ ‖r(to) − r(from)‖ that holds at every
  /// `to` where p has moved by at most `epsilon` from where it is at `from` (factors/SeenPointMove.h bounds that
  /// move from the variables); `chi2AtFrom` is ‖r(from)‖². Then ‖r(to)‖ lies within ‖r(from)‖ ± δ, known without
  /// evaluating r at `to`. std::nullopt for other factors (the default), under a robust kernel, or where `epsilon` is
  /// too large for a bound. MaxMixtureFactor::chooseAt uses it to say how far a choice holds.
  virtual std::optional<double> whitenedErrorBoundForSeenMove(const Values& /*from*/, double /*chi2AtFrom*/,
                                                              double /*epsilon*/) const {
    return std::nullopt;
  }

 private:
  std::vector<Key> keys_;
};

using FactorPtr = std::shared_ptr<const Factor>;

}  // namespace semslam
