#include "semslam/solve/BatchSmoother.h"

#include <stdexcept>

namespace semslam {

BatchSmoother::BatchSmoother(OptimizerParams params) : params_(params) {}

std::vector<FactorIndex> BatchSmoother::update(const FactorGraph& newFactors, const Values& newValues,
                                               const std::vector<FactorIndex>& removed) {
  for (FactorIndex index : removed) {
    if (index >= slots_.size() || !slots_[index]) {
      throw std::invalid_argument("BatchSmoother::update: no factor with index " + std::to_string(index));
    }
  }
  Values values = estimate_;
  values.insert(newValues);  // throws if a key exists
  for (const auto& factor : newFactors) {
    for (Key key : factor->keys()) {
      if (!values.exists(key)) {
        throw std::invalid_argument("BatchSmoother::update: a new factor names variable " + keyToString(key) +
                                    ", which has no value");
      }
    }
  }
  for (FactorIndex index : removed) slots_[index] = nullptr;
  std::vector<FactorIndex> indices;
  for (const auto& factor : newFactors) {
    indices.push_back(slots_.size());
    slots_.push_back(factor);
  }
  const FactorGraph graph = factors();
  if (graph.empty()) {
    lastResult_ = OptimizationResult();
    lastResult_.values = values;
  } else {
    lastResult_ = optimize(graph, values, params_);
  }
  estimate_ = lastResult_.values;
  marginals_.reset();
  return indices;
}

void BatchSmoother::replaceFactor(FactorIndex index, FactorPtr factor) {
  if (index >= slots_.size() || !slots_[index]) {
    throw std::invalid_argument("BatchSmoother::replaceFactor: no factor with index " + std::to_string(index));
  }
  if (!factor) throw std::invalid_argument("BatchSmoother::replaceFactor: null factor");
  for (Key key : factor->keys()) {
    if (!estimate_.exists(key)) {
      throw std::invalid_argument("BatchSmoother::replaceFactor: the factor names variable " + keyToString(key) +
                                  ", which has no value");
    }
  }
  slots_[index] = std::move(factor);
  marginals_.reset();
}

JointMarginal BatchSmoother::jointMarginal(const std::vector<Key>& keys) const {
  if (!marginals_) marginals_ = std::make_shared<const Marginals>(factors(), estimate_);
  return marginals_->jointMarginal(keys);
}

FactorGraph BatchSmoother::factors() const {
  FactorGraph graph;
  for (const auto& factor : slots_) {
    if (factor) graph.add(factor);
  }
  return graph;
}

FactorPtr BatchSmoother::factor(FactorIndex index) const { return slots_.at(index); }

std::unique_ptr<Smoother> BatchSmoother::fork() const { return std::make_unique<BatchSmoother>(*this); }

std::size_t BatchSmoother::memoryBytes() const {
  return vectorBytes(slots_) + estimate_.memoryBytes() + (marginals_ ? marginals_->memoryBytes() : 0);
}

}  // namespace semslam
