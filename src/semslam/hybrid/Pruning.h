#pragma once
// Pruning: PruneAndNormalize of Algorithm 1 (A sec. IV-C, V) on log-weights.
//
// Math. From log-weights ℓ_i (any offset; −∞ for a zero weight): w_i = exp(ℓ_i − max ℓ) / Σ_j exp(ℓ_j − max ℓ);
// component i survives iff w_i ≥ w_max / ratio (ratio ≤ 1: every component with w_i > 0 survives); when
// maxComponents > 0 only the maxComponents heaviest survivors are kept (ties: lower index first); survivors'
// weights are renormalised to sum to one.
//
// Invariants of the result (tested): kept is non-empty and in increasing index order, weights[i] > 0 sum to one,
// the heaviest input (lowest index among ties) is kept, and every kept input weight was ≥ w_max / ratio.
// All ℓ_i = −∞, or any NaN or +∞, throws std::invalid_argument.

#include <cstddef>
#include <vector>

namespace semslam {

struct PruningResult {
  std::vector<std::size_t> kept;  ///< indices into the input, increasing
  std::vector<double> weights;    ///< normalised weights of the kept, same order
  double prunedMass = 0.0;        ///< Σ of the normalised input weights that were pruned
  std::size_t capped = 0;         ///< inputs that passed the ratio but not the maxComponents cap
};

PruningResult pruneAndNormalize(const std::vector<double>& logWeights, double ratio, int maxComponents = 0);

/// w_i = exp(ℓ_i − max ℓ) / Σ_j exp(ℓ_j − max ℓ).
std::vector<double> normalizeLogWeights(const std::vector<double>& logWeights);

}  // namespace semslam
