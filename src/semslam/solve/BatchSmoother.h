#pragma once
// BatchSmoother: the Smoother that re-solves the whole graph with Gauss-Newton or Levenberg-Marquardt at every
// update(), warm-started from the current estimate. Marginals are factored lazily once per estimate and shared
// between forks until either is updated.
//
// Invariants: slots_[i] is the factor with index i, or null once removed; estimate_ holds a value for every
// variable any factor in force names.

#include <memory>

#include "semslam/solve/Marginals.h"
#include "semslam/solve/Optimizer.h"
#include "semslam/solve/Smoother.h"

namespace semslam {

class BatchSmoother final : public Smoother {
 public:
  explicit BatchSmoother(OptimizerParams params = {});

  std::vector<FactorIndex> update(const FactorGraph& newFactors = {}, const Values& newValues = {},
                                  const std::vector<FactorIndex>& removed = {}) override;
  void replaceFactor(FactorIndex index, FactorPtr factor) override;
  using Smoother::estimate;
  const Values& estimate() const override { return estimate_; }
  JointMarginal jointMarginal(const std::vector<Key>& keys) const override;
  FactorGraph factors() const override;
  FactorPtr factor(FactorIndex index) const override;
  std::unique_ptr<Smoother> fork() const override;
  std::size_t memoryBytes() const override;

  /// The result of the last solve (iterations, chi2, stop reason).
  const OptimizationResult& lastResult() const { return lastResult_; }

 private:
  OptimizerParams params_;
  std::vector<FactorPtr> slots_;
  Values estimate_;
  OptimizationResult lastResult_;
  mutable std::shared_ptr<const Marginals> marginals_;  // at estimate_, built on first use
};

}  // namespace semslam
