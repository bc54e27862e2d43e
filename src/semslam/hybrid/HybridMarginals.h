#pragma once
// HybridMarginals: what a hybrid belief says at time k (A, eq. 6-8).
//
//   components         each component as a HypothesisComponent (models/HypothesisComponent.h): weight, β_1:k with the log's object ids
//                      (−1 for a dropped detection), the class of every object (−1: not associated, collapsed),
//                      mean and covariance (right perturbation, translation first) of the current pose x_k;
//   ancestors          per component, the index of the component of step k − 1 it branched from (−1 at k = 0);
//   association        P(β_1:k | H_k) = Σ_C w^C_β1:k (eq. 8), heaviest first;
//   classes            P(c_j = m | H_k) = Σ_i w_i P_i(c_j = m) (eq. 7, per object), where a component with c_j
//                      collapsed contributes its weight uniformly, P_i(c_j = m) = 1/M (exact under the uniform
//                      class prior, A sec. IV-D); empty without semantics;
//   mixture            the mixture posterior over the current position (eq. 6) summarised by its first two
//                      moments in the world frame: μ = Σ w_i μ_i, Σ = Σ w_i (R_i Σ_i,tt R_iᵀ + (μ_i − μ)(μ_i − μ)ᵀ),
//                      Σ_i,tt the translation block of the component's tangent covariance and R_i its rotation
//                      (2 or 3 entries: the log's dimension);
// Paper A's metrics of these (entropy, det Σ, errors against the true pose) are eval/HypothesisMetrics.h's; the
// estimator computes none of them.

#include <optional>
#include <vector>

#include "semslam/hybrid/HybridBelief.h"
#include "semslam/models/HypothesisComponent.h"

namespace semslam {

struct HybridMarginals {
  int step = 0;
  std::vector<HypothesisComponent> components;
  std::vector<int> ancestors;
  std::vector<AssociationHypothesis> association;
  Matrix classes;  ///< N x M, empty without semantics
  Vector mixtureMean;        ///< d = the log's dimension
  Matrix mixtureCovariance;  ///< d x d
};

/// The marginals of `belief` at its current step.
HybridMarginals hybridMarginals(const HybridBelief& belief);

}  // namespace semslam
