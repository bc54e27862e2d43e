#include "semslam/hybrid/Pruning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace semslam {

std::vector<double> normalizeLogWeights(const std::vector<double>& logWeights) {
  double maximum = -std::numeric_limits<double>::infinity();
  for (double l : logWeights) {
    if (std::isnan(l) || l == std::numeric_limits<double>::infinity()) {
      throw std::invalid_argument("weights: a log-weight is NaN or +inf");
    }
    maximum = std::max(maximum, l);
  }
  if (!std::isfinite(maximum)) throw std::invalid_argument("weights: every weight is zero");
  std::vector<double> weights(logWeights.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < weights.size(); ++i) sum += weights[i] = std::exp(logWeights[i] - maximum);
  for (double& w : weights) w /= sum;
  return weights;
}

PruningResult pruneAndNormalize(const std::vector<double>& logWeights, double ratio, int maxComponents) {
  const std::vector<double> weights = normalizeLogWeights(logWeights);
  const double heaviest = *std::max_element(weights.begin(), weights.end());
  const double threshold = ratio > 1.0 ? heaviest / ratio : 0.0;
  std::vector<std::size_t> survivors;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] > 0.0 && weights[i] >= threshold) survivors.push_back(i);
  }
  PruningResult result;
  if (maxComponents > 0 && survivors.size() > static_cast<std::size_t>(maxComponents)) {
    result.capped = survivors.size() - static_cast<std::size_t>(maxComponents);
    std::stable_sort(survivors.begin(), survivors.end(),
                     [&](std::size_t a, std::size_t b) { return weights[a] > weights[b]; });
    survivors.resize(static_cast<std::size_t>(maxComponents));
    std::sort(survivors.begin(), survivors.end());
  }
  result.kept = survivors;
  double keptMass = 0.0;
  for (std::size_t i : survivors) keptMass += weights[i];
  for (std::size_t i : survivors) result.weights.push_back(weights[i] / keptMass);
  result.prunedMass = std::max(0.0, 1.0 - keptMass);
  return result;
}

}  // namespace semslam
