#include "semslam/graph/FactorGraph.h"

#include <algorithm>
#include <stdexcept>

namespace semslam {

void FactorGraph::add(FactorPtr factor) {
  if (!factor) throw std::invalid_argument("FactorGraph::add: null factor");
  factors_.push_back(std::move(factor));
}

void FactorGraph::add(const FactorGraph& other) {
  factors_.insert(factors_.end(), other.factors_.begin(), other.factors_.end());
}

double FactorGraph::chi2(const Values& values) const {
  double total = 0.0;
  for (const auto& factor : factors_) total += factor->chi2(values);
  return total;
}

std::vector<Key> FactorGraph::keys() const {
  std::vector<Key> result;
  for (const auto& factor : factors_) result.insert(result.end(), factor->keys().begin(), factor->keys().end());
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

}  // namespace semslam
