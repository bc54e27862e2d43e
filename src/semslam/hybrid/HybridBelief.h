#pragma once
// HybridBelief: paper A's hybrid belief P(X_k, C, β_1:k | H_k) = Σ w^C_β1:k b[X_k]^C_β1:k (eq. 4-5) and its
// recursive update, Algorithm 1.
//
// Construction: one component with weight 1, no history, classes all collapsed (−1; or, with
// enumerateAllClasses, M^N components of weight M^−N, one per class realization), and a smoother holding the
// priors of x_0 and of every object (eq. 3).
// update(step) at time k (the k-th call, k = 0, 1, ...):
//   1. propagate (Alg. 1 line 3, eq. 11): for k > 0, each component's smoother is forked and given the motion
//      factor x_{k−1} → x_k with x_k initialised by the odometry from the component's estimate of x_{k−1};
//   2. PropWeights (lines 4-5, eq. 15-17; PropWeights.h): candidate children and their weights, from the joint
//      marginal of x_k and all objects of each propagated parent (computed once per parent);
//   3. PruneAndNormalize (line 7; Pruning.h), globally over all children;
//   4. observation update (lines 9-11, eq. 9-10): each surviving child forks its parent's propagated smoother and
//      adds its detections' factors.
// Weights are normalised after every update. Components are kept in candidate order (parents in order, then β
// in enumeration order), so a seed gives the same belief bit for bit.

#include <random>
#include <vector>

#include "semslam/hybrid/HybridComponent.h"
#include "semslam/hybrid/HybridOptions.h"
#include "semslam/hybrid/HybridProblem.h"
#include "semslam/hybrid/PropWeights.h"

namespace semslam {

struct HybridStepReport {
  int step = 0;
  std::size_t parents = 0;
  std::size_t survivors = 0;
  double prunedMass = 0.0;
  std::size_t cappedComponents = 0;  ///< survivors of the pruning ratio dropped by HybridOptions::maxComponents
  std::size_t memoryCappedComponents = 0;  ///< of those, dropped because HybridOptions::maxMemoryMiB bound first
  double componentBytes = 0.0;       ///< the estimate per child component the memory bound used (bytes)
  PropWeightsReport weights;
  double seconds = 0.0;
};

class HybridBelief {
 public:
  HybridBelief(const HybridProblem& problem, HybridOptions options);

  /// Applies one time step (odometry required for every step after the first). Returns what happened.
  HybridStepReport update(const TimeStep& step);

  const std::vector<HybridComponent>& components() const { return components_; }
  /// Steps applied so far; the current pose is poseKey(steps() − 1).
  int steps() const { return steps_; }
  const HybridProblem& problem() const { return problem_; }
  /// Index of the heaviest component (the first among ties).
  std::size_t heaviest() const;

 private:
  const HybridProblem& problem_;
  HybridOptions options_;
  std::vector<HybridComponent> components_;
  std::mt19937 rng_;
  int steps_ = 0;
};

}  // namespace semslam
