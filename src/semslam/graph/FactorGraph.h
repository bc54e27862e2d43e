#pragma once
// FactorGraph: an ordered collection of shared, immutable factors. Copying a graph copies pointers only.

#include <memory>
#include <utility>
#include <vector>

#include "semslam/graph/Factor.h"

namespace semslam {

class FactorGraph {
 public:
  using const_iterator = std::vector<FactorPtr>::const_iterator;

  FactorGraph() = default;
  explicit FactorGraph(std::vector<FactorPtr> factors) : factors_(std::move(factors)) {}

  void add(FactorPtr factor);
  void add(const FactorGraph& other);
  /// Builds a factor of type F in place: graph.emplace<BetweenFactor<SE2>>(i, j, z, noise).
  template <class F, class... Args>
  void emplace(Args&&... args) {
    add(std::make_shared<const F>(std::forward<Args>(args)...));
  }

  std::size_t size() const { return factors_.size(); }
  /// Heap bytes of the factor list itself; the factors are shared and not counted.
  std::size_t memoryBytes() const { return factors_.capacity() * sizeof(FactorPtr); }
  bool empty() const { return factors_.empty(); }
  const FactorPtr& operator[](std::size_t i) const { return factors_[i]; }
  const_iterator begin() const { return factors_.begin(); }
  const_iterator end() const { return factors_.end(); }

  /// Σ_f chi2_f(values): twice the objective.
  double chi2(const Values& values) const;

  /// Every key some factor touches, sorted and unique.
  std::vector<Key> keys() const;

 private:
  std::vector<FactorPtr> factors_;
};

}  // namespace semslam
