#include "semslam/hybrid/HybridMarginals.h"

namespace semslam {

HybridMarginals hybridMarginals(const HybridBelief& belief) {
  const HybridProblem& problem = belief.problem();
  const int k = belief.steps() - 1;
  const Key pose = poseKey(static_cast<std::uint64_t>(k));
  HybridMarginals out;
  out.step = k;
  for (const HybridComponent& c : belief.components()) {
    HypothesisComponent h;
    h.weight = c.weight;
    h.associations = c.history;
    out.ancestors.push_back(c.ancestor);
    h.classes = c.classes;
    h.pose = c.smoother->estimate<SE2>(pose);
    h.covariance = c.smoother->marginalCovariance(pose);
    out.components.push_back(std::move(h));
  }
  out.association = associationMarginal(out.components);  // P(β_1:k | H_k) = Σ_C w^C_β1:k (A, eq. 8)
  if (problem.enumeratesClasses()) {  // P(C | H_k) = Σ_β w^C_β1:k per object (A, eq. 7); collapsed: uniform
    const int m = problem.classes();
    out.classes = Matrix::Zero(problem.objects(), m);
    for (const HybridComponent& c : belief.components()) {
      for (int j = 0; j < problem.objects(); ++j) {
        if (c.classes[j] >= 0) out.classes(j, c.classes[j]) += c.weight;
        else out.classes.row(j).array() += c.weight / m;
      }
    }
  }
  // The mixture Σ w b[x_k] (A, eq. 6) by its first two moments.
  for (const HypothesisComponent& h : out.components) out.mixtureMean += h.weight * std::get<SE2>(h.pose).translation();
  for (const HypothesisComponent& h : out.components) {
    const SE2& x = std::get<SE2>(h.pose);
    const Matrix2 R = x.rotation().matrix();
    const Vector2 d = x.translation() - out.mixtureMean;
    out.mixtureCovariance += h.weight * (R * h.covariance.topLeftCorner<2, 2>() * R.transpose() + d * d.transpose());
  }
  return out;
}

}  // namespace semslam
