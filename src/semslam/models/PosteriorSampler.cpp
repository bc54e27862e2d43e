#include "semslam/models/PosteriorSampler.h"

#include <cmath>
#include <stdexcept>

#include "semslam/models/Sampling.h"

namespace semslam {

PosteriorSampler::PosteriorSampler(const FactorGraph& graph, const Values& optimum)
    : optimum_(optimum), marginals_(graph, optimum) {
  for (std::size_t f = 0; f < graph.size(); ++f) errorDimensions_.push_back(graph[f]->errorDimension());
}

Values PosteriorSampler::draw(double scale, std::mt19937& rng) const {
  if (!(scale >= 0.0) || !std::isfinite(scale)) {
    throw std::invalid_argument("posterior draw: the scale must be finite and >= 0");
  }
  std::vector<Vector> perturbation;  // v ~ N(0, I), one block per factor's whitened error
  perturbation.reserve(errorDimensions_.size());
  for (int dimension : errorDimensions_) {
    Vector v(dimension);
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = standardNormal(rng);
    perturbation.push_back(std::move(v));
  }
  return marginals_.retract(optimum_, scale * marginals_.posteriorOffset(perturbation));  // X̂ ⊕ s H⁻¹ Jᵀ v
}

}  // namespace semslam
