#pragma once
// Smoother: the estimation back end every method talks to. It owns a growing factor graph and the current
// estimate of all its variables (a full smoothing belief: every pose and landmark, not only the latest).
//
//   update(new factors, new values, removed)  adds factors (each gets a FactorIndex, stable for the smoother's
//                                             lifetime), initial values for new variables, removes factors by
//                                             index, and re-solves;
//   replaceFactor(index, factor)              swaps one factor for another (a max-mixture switching component,
//                                             an EM re-weighting); it takes effect at the next update();
//   estimate()                                the current MAP estimate;
//   jointMarginal(keys)                       the joint Gaussian marginal of any set of variables at the estimate;
//   fork()                                    a cheap copy that shares every factor with the original (factors are
//                                             immutable), for the branching hypotheses of the hybrid belief.
//
// Implementations: BatchSmoother (re-solves the whole graph each update) and IncrementalSmoother (a Bayes tree,
// iSAM2-style: re-eliminates only what an update affects; its marginals are at its linearization point, within
// the relinearization threshold of the estimate: docs/incremental-smoother.md).
// Smoothers are not thread-safe; forks are independent and may be used from different threads.

#include <memory>
#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"
#include "semslam/solve/JointMarginal.h"

namespace semslam {

using FactorIndex = std::size_t;

class Smoother {
 public:
  virtual ~Smoother() = default;

  /// Adds factors and values for new variables, removes the factors `removed`, re-solves. Returns the indices
  /// of the new factors, in order. Throws std::invalid_argument for a value whose key exists, an unknown or
  /// already removed index, or a factor naming a variable that has no value.
  virtual std::vector<FactorIndex> update(const FactorGraph& newFactors = {}, const Values& newValues = {},
                                          const std::vector<FactorIndex>& removed = {}) = 0;

  /// Replaces the factor at `index` (its keys may differ); takes effect at the next update().
  virtual void replaceFactor(FactorIndex index, FactorPtr factor) = 0;

  virtual const Values& estimate() const = 0;
  template <class T>
  const T& estimate(Key key) const {
    return estimate().at<T>(key);
  }

  /// Joint marginal covariance of `keys` at the current estimate.
  virtual JointMarginal jointMarginal(const std::vector<Key>& keys) const = 0;
  Matrix marginalCovariance(Key key) const { return jointMarginal({key}).covariance(); }

  /// The factors in force, in index order (removed ones left out).
  virtual FactorGraph factors() const = 0;
  /// The factor with `index` (after any replaceFactor), or null once removed; throws std::out_of_range for an
  /// index never given.
  virtual FactorPtr factor(FactorIndex index) const = 0;

  /// Iterates to the optimum of the factors in force. A batch smoother is there after every update (no-op); an
  /// incremental one keeps an estimate one Gauss-Newton step from its linearization point, which this refines.
  virtual void converge() {}

  /// A copy that shares all factors with this one; updating either leaves the other unchanged.
  virtual std::unique_ptr<Smoother> fork() const = 0;

  /// Heap bytes this smoother holds, counted from its containers' sizes (core/MemoryBytes.h): its estimate, its
  /// index of the factors, and whatever it caches (linearizations, factorizations, a Bayes tree), counting what
  /// it still shares with a fork as its own (an upper bound of what one more fork costs). The factors, shared by
  /// every fork, are not counted. Deterministic; the hybrid belief's memory bound reads it.
  virtual std::size_t memoryBytes() const = 0;
};

}  // namespace semslam
