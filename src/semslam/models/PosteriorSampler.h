#pragma once
// PosteriorSampler: joint draws from a factor graph's posterior in its Laplace (Gauss-Newton) approximation at an
// optimum X̂,
//
//     X̃ = X̂ ⊕ s δ,   δ ~ N(0, H⁻¹),   H = JᵀJ
//
// (J: every factor's whitened Jacobian at X̂, NormalEquations.h; s a scale, 1 for the posterior itself). δ is drawn
// by perturbation, without forming any factor of H⁻¹:
//
//     δ = H⁻¹ Jᵀ v,   v ~ N(0, I_m)  (one standard normal per whitened error entry, factors in graph order),
//
// so Cov(δ) = H⁻¹ JᵀJ H⁻¹ = H⁻¹: the spread of the least-squares solution when every measurement is perturbed by its
// own noise (G. Papandreou and A. Yuille, "Gaussian sampling by local perturbations", NIPS 2010). The draw is joint:
// the variables' errors are correlated as the posterior says, so the relative errors of a trajectory drawn this way
// are the ones its estimate has, where independent draws from each pose's marginal give consecutive poses
// independent errors (relative errors of √2 σ_marginal, the whole drift's uncertainty at every step).
//
// Cost: H is assembled and factorised once (solve/Marginals.h, which applies H⁻¹Jᵀ); each draw is one Jᵀv and one
// solve.
// Invariants: the same graph, optimum, scale and engine state give the same draw, bit for bit; a draw consumes
// m standardNormal values (models/Sampling.h). Robust kernels and max-mixtures enter as they linearise at X̂.

#include <random>

#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"
#include "semslam/solve/Marginals.h"

namespace semslam {

class PosteriorSampler {
 public:
  /// Linearises `graph` at `optimum` and factorises H (Marginals). Throws std::invalid_argument for a graph without
  /// factors, UnconstrainedSystemError (solve/UnconstrainedSystem.h) when H is not positive definite.
  PosteriorSampler(const FactorGraph& graph, const Values& optimum);

  /// X̂ ⊕ scale · δ for one draw of δ (above); variables that no factor names are copied unchanged. Throws
  /// std::invalid_argument for a negative or non-finite scale.
  Values draw(double scale, std::mt19937& rng) const;

 private:
  Values optimum_;
  Marginals marginals_;
  std::vector<int> errorDimensions_;  // of each factor's whitened error, in graph order
};

}  // namespace semslam
