#include "semslam/models/PosteriorSampler.h"

#include <cmath>
#include <stdexcept>

#include "semslam/models/Sampling.h"
#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam {
namespace {

const FactorGraph& nonEmpty(const FactorGraph& graph) {
  if (graph.empty()) throw std::invalid_argument("PosteriorSampler: the graph has no factors, so no posterior");
  return graph;
}

}  // namespace

PosteriorSampler::PosteriorSampler(const FactorGraph& graph, const Values& optimum)
    : graph_(nonEmpty(graph)), optimum_(optimum), system_(graph, optimum) {
  system_.assemble(optimum);
  cholesky_.analyze(system_.hessian());
  if (!cholesky_.factorize(system_.hessian())) throwUnconstrained(graph, optimum);
  for (std::size_t f = 0; f < graph_.size(); ++f) errorDimension_ += graph_[f]->errorDimension();
}

Values PosteriorSampler::draw(double scale, std::mt19937& rng) const {
  if (!(scale >= 0.0) || !std::isfinite(scale)) {
    throw std::invalid_argument("posterior draw: the scale must be finite and >= 0");
  }
  std::vector<Vector> perturbation;  // v ~ N(0, I), one block per factor's whitened error
  perturbation.reserve(graph_.size());
  for (std::size_t f = 0; f < graph_.size(); ++f) {
    Vector v(graph_[f]->errorDimension());
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = standardNormal(rng);
    perturbation.push_back(std::move(v));
  }
  const Vector delta = cholesky_.solve(system_.transposedJacobianTimes(perturbation));  // H⁻¹ Jᵀ v
  return system_.retract(optimum_, scale * delta);
}

}  // namespace semslam
