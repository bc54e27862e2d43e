#include "CeresPoseGraph.h"

#include <algorithm>
#include <stdexcept>

#include "FactorCostFunction.h"

namespace semslam::bench {

ceres::Solver::Options ceresOptions(int threads) {
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
  options.num_threads = threads;
  // Our optimizer stops on a relative decrease of 1e-10 (or a gradient 1e-10 of the initial one, or a step of
  // 1e-12) within 100 linear solves; Ceres gets the same thresholds (its gradient test is absolute).
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-10;
  options.gradient_tolerance = 1e-10;
  options.parameter_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  return options;
}

CeresPoseGraph::CeresPoseGraph(const FactorGraph& graph, const Values& initial) {
  keys_ = graph.keys();
  kinds_.reserve(keys_.size());
  offsets_.reserve(keys_.size());
  int size = 0;
  for (Key key : keys_) {
    if (!initial.exists(key)) {
      throw std::invalid_argument("a factor names variable " + keyToString(key) + ", which has no value");
    }
    const Value& value = initial.value(key);
    kinds_.push_back(kindOf(value));
    offsets_.push_back(size);
    size += dimension(value);
  }
  parameters_.resize(size);
  for (std::size_t v = 0; v < keys_.size(); ++v) toAmbient(initial.value(keys_[v]), &parameters_[offsets_[v]]);

  ceres::Problem::Options problemOptions;
  problemOptions.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;  // shared, owned by manifolds_
  problem_ = std::make_unique<ceres::Problem>(problemOptions);
  for (std::size_t v = 0; v < keys_.size(); ++v) {
    std::unique_ptr<ValueManifold>& manifold = manifolds_[kinds_[v]];
    if (!manifold) manifold = std::make_unique<ValueManifold>(kinds_[v]);
    problem_->AddParameterBlock(&parameters_[offsets_[v]], ambientSize(kinds_[v]), manifold.get());
  }

  std::vector<double*> blocks;
  std::vector<ValueKind> kinds;
  for (const FactorPtr& factor : graph) {
    blocks.clear();
    kinds.clear();
    for (Key key : factor->keys()) {
      const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
      const auto v = static_cast<std::size_t>(it - keys_.begin());
      blocks.push_back(&parameters_[offsets_[v]]);
      kinds.push_back(kinds_[v]);
    }
    problem_->AddResidualBlock(new FactorCostFunction(factor, kinds), nullptr, blocks);
  }
}

ceres::Solver::Summary CeresPoseGraph::solve(const ceres::Solver::Options& options) {
  ceres::Solver::Summary summary;
  ceres::Solve(options, problem_.get(), &summary);
  return summary;
}

Values CeresPoseGraph::values() const {
  Values result;
  for (std::size_t v = 0; v < keys_.size(); ++v) result.insert(keys_[v], fromAmbient(kinds_[v], &parameters_[offsets_[v]]));
  return result;
}

}  // namespace semslam::bench
