#pragma once
// HybridMarginals: what a hybrid belief says at time k (A, eq. 6-8), and paper A's metrics of it.
//
//   components         each component as eval's HypothesisComponent: weight, β_1:k with the log's object ids
//                      (−1 for a dropped detection), the class of every object (−1: not associated, collapsed),
//                      mean and covariance (right perturbation, translation first) of the current pose x_k;
//   association        P(β_1:k | H_k) = Σ_C w^C_β1:k (eq. 8), heaviest first;
//   classes            P(c_j = m | H_k) = Σ_i w_i P_i(c_j = m) (eq. 7, per object), where a component with c_j
//                      collapsed contributes its weight uniformly, P_i(c_j = m) = 1/M (exact under the uniform
//                      class prior, A sec. IV-D); empty without semantics;
//   mixture            the mixture posterior over the current position (eq. 6) summarised by its first two
//                      moments in the world frame: μ = Σ w_i μ_i, Σ = Σ w_i (R_i Σ_i,tt R_iᵀ + (μ_i − μ)(μ_i − μ)ᵀ),
//                      Σ_i,tt the translation block of the component's tangent covariance and R_i its rotation;
//   metrics            eval/HypothesisMetrics.h's entropy over the association marginal (eq. 8), det Σ of the
//                      heaviest component's position, x̃^{w_max}, x̃^{w_avg}, ESS, max_β P(β | H_k).

#include <optional>
#include <vector>

#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/hybrid/HybridBelief.h"

namespace semslam {

struct HybridMarginals {
  int step = 0;
  std::vector<HypothesisComponent> components;
  std::vector<AssociationHypothesis> association;
  Matrix classes;  ///< N x M, empty without semantics
  Vector2 mixtureMean = Vector2::Zero();
  Matrix2 mixtureCovariance = Matrix2::Zero();
  HypothesisMetrics metrics;
};

/// The marginals of `belief` at its current step; `truePose` enables the errors.
HybridMarginals hybridMarginals(const HybridBelief& belief, const std::optional<Pose>& truePose);

}  // namespace semslam
