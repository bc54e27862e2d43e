#pragma once
// AutodiffPoseGraph2: a 2D pose graph written the way a Ceres user would write it, as a control for the
// wrapped comparison: each pose is a plain (x, y, θ) parameter block without a manifold, and each edge a
// ceres::AutoDiffCostFunction of a templated residual, so no semslam code runs inside Ceres's loop.
//
// The residual is our BetweenFactor<SE2> / PriorFactor<SE2> error, e = Log(z⁻¹ · x_i⁻¹ · x_j) with the exact
// SE2 log (θ wrapped to (-π, π], ρ = V(θ)⁻¹ t), whitened by the factor's square-root information; so the
// objective is the same function of the poses as ours and the optimum is the same. Only the update differs:
// Ceres adds the step to (x, y, θ) instead of composing Exp(δ) on the right.

#include <ceres/problem.h>
#include <ceres/solver.h>

#include <memory>
#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"

namespace semslam::bench {

class AutodiffPoseGraph2 {
 public:
  /// Throws std::invalid_argument unless every factor is a BetweenFactor<SE2> or PriorFactor<SE2> on SE2
  /// values present in `initial`.
  AutodiffPoseGraph2(const FactorGraph& graph, const Values& initial);
  AutodiffPoseGraph2(const AutodiffPoseGraph2&) = delete;
  AutodiffPoseGraph2& operator=(const AutodiffPoseGraph2&) = delete;

  ceres::Solver::Summary solve(const ceres::Solver::Options& options);
  Values values() const;

 private:
  std::vector<Key> keys_;       // sorted
  std::vector<double> poses_;   // (x, y, θ) per key
  std::unique_ptr<ceres::Problem> problem_;
};

}  // namespace semslam::bench
