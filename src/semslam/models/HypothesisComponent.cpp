#include "semslam/models/HypothesisComponent.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <string>

#include "semslam/core/InputError.h"
#include "semslam/core/PairwiseSum.h"

namespace semslam {

std::vector<double> componentWeights(const std::vector<HypothesisComponent>& components) {
  std::vector<double> weights;
  weights.reserve(components.size());
  for (const HypothesisComponent& c : components) weights.push_back(c.weight);
  return weights;
}

std::vector<double> normalizeWeights(const std::vector<double>& weights) {
  if (weights.empty()) throw InputError("weights: none given");
  for (double w : weights) {
    if (!(w >= 0.0) || !std::isfinite(w)) throw InputError("weights: a weight is negative or not finite");
  }
  const double sum = pairwiseSum(weights.data(), weights.size());
  if (!(sum > 0.0)) throw InputError("weights: they sum to zero");
  std::vector<double> normalized(weights.size());
  for (std::size_t i = 0; i < weights.size(); ++i) normalized[i] = weights[i] / sum;
  return normalized;
}

std::vector<AssociationHypothesis> associationMarginal(const std::vector<HypothesisComponent>& components) {
  const std::vector<double> weights = normalizeWeights(componentWeights(components));
  std::unordered_map<AssociationHistory, std::size_t, AssociationHistoryHash> index;  // history -> out's entry
  std::vector<AssociationHypothesis> out;
  for (std::size_t i = 0; i < components.size(); ++i) {
    const auto [entry, inserted] = index.try_emplace(components[i].associations, out.size());
    if (inserted) out.push_back({components[i].associations, 0.0, i});
    out[entry->second].weight += weights[i];
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const AssociationHypothesis& a, const AssociationHypothesis& b) { return a.weight > b.weight; });
  return out;
}

Matrix classMarginals(const std::vector<HypothesisComponent>& components, int classes) {
  if (classes < 1) throw InputError("class marginals: the number of classes must be >= 1");
  const std::vector<double> weights = normalizeWeights(componentWeights(components));
  const std::size_t objects = components.front().classes.size();
  Matrix marginal = Matrix::Zero(static_cast<Eigen::Index>(objects), classes);
  for (std::size_t i = 0; i < components.size(); ++i) {
    const std::vector<int>& c = components[i].classes;
    if (c.size() != objects) {
      throw InputError("class marginals: component " + std::to_string(i) + " has " + std::to_string(c.size()) +
                       " objects, component 0 has " + std::to_string(objects));
    }
    for (std::size_t j = 0; j < objects; ++j) {
      if (c[j] < 0 || c[j] >= classes) {
        throw InputError("class marginals: component " + std::to_string(i) + " gives object " + std::to_string(j) +
                         " class " + std::to_string(c[j]) + ", outside [0, " + std::to_string(classes) + ")");
      }
      marginal(static_cast<Eigen::Index>(j), c[j]) += weights[i];
    }
  }
  return marginal;
}

}  // namespace semslam
