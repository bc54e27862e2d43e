#include "semslam/hybrid/HybridMarginals.h"

#include "semslam/models/ValueConversions.h"

namespace semslam {
namespace {

Vector positionOf(const Pose& pose) {
  return std::visit([](const auto& x) -> Vector { return x.translation(); }, pose);
}

Matrix rotationOf(const Pose& pose) {
  return std::visit([](const auto& x) -> Matrix { return x.rotation().matrix(); }, pose);
}

}  // namespace

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
    h.pose = toPose(c.smoother->estimate().value(pose));
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
  const int d = problem.header().dimension;
  out.mixtureMean = Vector::Zero(d);
  out.mixtureCovariance = Matrix::Zero(d, d);
  for (const HypothesisComponent& h : out.components) out.mixtureMean += h.weight * positionOf(h.pose);
  for (const HypothesisComponent& h : out.components) {
    const Matrix R = rotationOf(h.pose);
    const Vector offset = positionOf(h.pose) - out.mixtureMean;
    out.mixtureCovariance +=
        h.weight * (R * h.covariance.topLeftCorner(d, d) * R.transpose() + offset * offset.transpose());
  }
  return out;
}

}  // namespace semslam
