#pragma once
// PropWeights: the candidate associations β_k of one time step and their weights (A, Algorithm 1, eq. 15-17).
//
// Candidates. For each propagated component (parent) and each assignment β_k of the step's n detections to
// distinct objects (A sec. III), and, with semantics, each class of every object that β_k associates for the
// first time in that parent (A sec. IV-D: classes of unassociated objects stay collapsed), one candidate child.
//   WholeAssociation       every such β_k (N!/(N−n)! of them), as Algorithm 1 does;
//   OneDetectionAtATime    detection by detection: each partial association is extended by every unused object
//                          whose stacked innovation over the detections so far passes the χ² test at the joint
//                          compatibility confidence (the JCBB test on the joint marginal); partial hypotheses are
//                          pruned by linearised weight (w < w_max / gateRatio) between detections. A detection
//                          that no partial association can take is dropped (β = −1) for every candidate.
//
// Weights. With F the stacked factors of the candidate's detections (geometric and viewpoint-semantic, eq. 10)
// and Σ the joint marginal of x_k and the associated objects under the parent's propagated belief (eq. 17):
//   linearised   ℓ_lin = log w_parent + log N(r̄; 0, JΣJᵀ + I) + log-constants     (MarginalLikelihood.h)
//                over the geometric factors in Cartesian form (CartesianGateFactor.h: accurate far from the
//                linearisation point) and the semantic factors;
//   gate         ℓ_gate: the same over the Cartesian geometric factors only (semantics can only sharpen it, and
//                their linearisation in θ is poor under a broad prior);
//   sampled      ℓ     = log w_parent + log (1/n_s) Σ_s P(Z | X_s) P(β | X_s) + log-constants     (eq. 16)
//                with P(β | X_s) the visibility indicator (VisibilityModel2::associationFeasible) when enabled,
//                X_s drawn from the joint marginal (eq. 17) of x_k and the objects that the parent's ungated
//                candidates associate, once per parent: the candidates of one parent are weighed on the same n_s
//                draws (MarginalSamples, common random numbers). Both factors of the integrand factor over the
//                detections, P(Z | X_s) = Π_i P(z_i | x_s, o_s(i)) and the indicator = Π_i 1[o(i) visible from x_s],
//                so each (detection, object, class) term and each object's visibility is computed once per draw
//                and a candidate's log-integrand is their sum;
//   importance   ℓ     = log w_parent + log (1/n_s) Σ_s P(Z | X_s) P(β | X_s) N(X_s; X̄, Σ) / q(X_s) + log-constants
//                with X_s drawn from q, the linearised posterior of the joint variables given F
//                (ImportanceSampledLikelihood.h): the same integral with far fewer wasted samples under broad priors;
//   log-constants: Σ_i log P(z_sem,i | c) for the categorical model, and log(1/M) per newly associated object
//                  (the class prior, eq. 3).
// Gate: before sampling, a candidate whose ℓ_gate < max ℓ_gate − log(gateRatio) is skipped (weight 0); the
// linearised mass it held, Σ_gated exp(ℓ_gate) / Σ_all exp(ℓ_gate), is reported as the gate's lost mass.
// The joint-compatibility test of one-detection-at-a-time branching uses the gate factors' innovation.
// Bounds (HybridOptions: maxCandidates): whole-association branching first counts an upper bound of its
// candidates, Σ_parents N!/(N−n)! · M^n, and past options.maxCandidates branches one detection at a time instead;
// one-detection-at-a-time branching keeps at most options.maxCandidates partial associations (the heaviest by
// linearised gate weight, earlier first among ties), pruning its working list whenever it reaches twice that, so
// no step holds more than 2 · maxCandidates candidates.
// Fallback: when every sampled weight is zero (no sample makes any candidate visible), the linearised weights
// are used for that step and the fallback is reported.

#include <cstddef>
#include <random>
#include <vector>

#include "semslam/hybrid/HybridComponent.h"
#include "semslam/hybrid/HybridOptions.h"
#include "semslam/hybrid/HybridProblem.h"

namespace semslam {

struct AssociationCandidate {
  std::size_t parent = 0;
  std::vector<int> beta;            ///< object per detection, −1 dropped
  std::vector<int> classes;         ///< the parent's realization extended by the new objects' classes
  std::vector<FactorPtr> factors;   ///< stacked factors of the associated detections (the belief's)
  std::vector<FactorPtr> gateFactors;     ///< their geometric parts in the gate's form
  std::vector<FactorPtr> analyticFactors; ///< gate factors plus the semantic factors: the analytic weight's
  double logConstant = 0.0;
  double gateLogWeight = 0.0;       ///< log w_parent + linearised geometric log-likelihood + log-constants
  double linearizedLogWeight = 0.0; ///< log w_parent + linearised log-likelihood of analyticFactors + constants
  double innovationChi2 = 0.0;
  double logWeight = 0.0;           ///< the weight used (sampled or analytic); −∞ when gated
  double relativeStandardError = 0.0;
  bool gated = false;
};

/// What one step of PropWeights did.
struct PropWeightsReport {
  std::size_t candidates = 0;
  std::size_t gated = 0;
  std::size_t sampled = 0;
  double gateLostMass = 0.0;            ///< gate-linearised mass of the gated candidates
  double maxRelativeStandardError = 0.0;///< of the sampled weights that carry ≥ 1e-3 of the mass
  double analyticTotalVariation = 0.0;  ///< ½ Σ |w_sampled − w_lin| over the sampled candidates (normalised each)
  int droppedDetections = 0;
  bool fellBackToLinearized = false;
  bool branchedOneAtATime = false;      ///< WholeAssociation past options.maxCandidates: this step went one at a time
  double wholeAssociationBound = 0.0;   ///< WholeAssociation: the upper bound of the step's candidates counted
  std::size_t truncatedPartials = 0;    ///< OneDetectionAtATime: partial associations dropped by maxCandidates
  double samplingSeconds = 0.0;
};

/// A parent component after propagation: its belief at x_k and the joint marginal of x_k and every object.
struct PropagatedParent {
  const HybridComponent* component = nullptr;
  std::shared_ptr<const Smoother> smoother;
  JointMarginal joint;  ///< keys: x_k, then objects 0..N−1
};

/// Enumerates the candidates of `parents` for the detections of step k and computes their weights (unnormalised
/// log-weights in logWeight).
std::vector<AssociationCandidate> propagateWeights(const HybridProblem& problem, const HybridOptions& options,
                                                   const std::vector<PropagatedParent>& parents, int k,
                                                   const std::vector<Detection>& detections, std::mt19937& rng,
                                                   PropWeightsReport& report);

}  // namespace semslam
