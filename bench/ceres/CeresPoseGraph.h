#pragma once
// CeresPoseGraph: a semslam factor graph as a ceres::Problem, every factor a FactorCostFunction and every
// variable a parameter block in its ambient coordinates with a ValueManifold.
//
// The parameter blocks live in one contiguous array owned here (Ceres reads and writes the user's blocks only
// at the start and the end of Solve); there is one shared manifold per kind of value.

#include <ceres/problem.h>
#include <ceres/solver.h>

#include <array>
#include <memory>
#include <vector>

#include "AmbientCoordinates.h"
#include "ValueManifold.h"
#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"

namespace semslam::bench {

/// The Ceres settings of the comparison: Levenberg-Marquardt, sparse normal Cholesky with SuiteSparse
/// (CHOLMOD, as our solver uses), `threads` threads, tolerances tight enough to reach our solver's optimum, no
/// logging.
ceres::Solver::Options ceresOptions(int threads);

class CeresPoseGraph {
 public:
  /// Every variable the factors touch must have a value in `initial`; throws std::invalid_argument otherwise.
  CeresPoseGraph(const FactorGraph& graph, const Values& initial);
  CeresPoseGraph(const CeresPoseGraph&) = delete;
  CeresPoseGraph& operator=(const CeresPoseGraph&) = delete;

  ceres::Solver::Summary solve(const ceres::Solver::Options& options);

  /// The current estimate of every variable the factors touch.
  Values values() const;

 private:
  std::vector<Key> keys_;  // sorted
  std::vector<ValueKind> kinds_;
  std::vector<int> offsets_;
  std::vector<double> parameters_;
  std::array<std::unique_ptr<ValueManifold>, std::variant_size_v<Value>> manifolds_;  // outlive the problem
  std::unique_ptr<ceres::Problem> problem_;
};

}  // namespace semslam::bench
