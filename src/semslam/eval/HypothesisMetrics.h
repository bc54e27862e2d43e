#pragma once
// Metrics of a hybrid belief (paper A, Tchuiev, Feldman, Indelman): a set of weighted components, one per
// realization of the class realization C and the data-association history β_1:k, each with a Gaussian belief.
// Paper A, section V, reports four metrics at each time k (its Fig. 5 averages them over 50 runs):
//
//   association marginal (A, eq. 8)   P(β_1:k | H_k) = Σ_C w^C_β1:k   (weights of components with the same
//                                     history summed over class realizations)
//   class marginal       (A, eq. 7)   P(C | H_k) = Σ_β w^C_β; per object j: P(c_j = m) = Σ_{C: C_j = m} w
//   1) entropy           H = −Σ_β P(β) log P(β)  over the association marginal (natural log, 0 log 0 = 0).
//                        Paper A writes it over "the N_k non-pruned weights"; we take the association marginal
//                        so that splitting one history over class realizations does not count as ambiguity.
//                        0 when one history holds all the weight; log N for N equally likely histories.
//   2) det(Σ)            det of the position block of the current pose covariance of the heaviest component
//                        (the x, y block in 2D; x, y, z in 3D). The covariance is that of the right perturbation
//                        (translation first); det of that block equals det of the world-frame position covariance
//                        to first order (R Σ Rᵀ has the same determinant). Units m^(2d).
//   3) x̃^{w_max}         ‖p̂_k − p_k‖, the Euclidean position error of the heaviest component's current pose (m).
//   4) x̃^{w_avg}         Σ_i w_i ‖p̂_{k,i} − p_k‖, the weight-average of the components' position errors (m) —
//                        the average of the errors, not the error of the averaged position.
// Positions are compared in the belief's own frame, without alignment: the priors (initial pose, prior map)
// fix that frame, and the covariance describes errors in it.
//
// Also:
//   ESS                  1 / Σ_i w_i² over the normalised weights of all components (C, β_1:k): the effective
//                        number of hypotheses, between 1 (one component holds everything) and N (all equal).
//                        These are the Monte Carlo weights of paper A (eq. 16 estimates each by averaging over
//                        sampled poses); this is the ESS of the hypothesis weights, not of the samples inside
//                        one such average (effectiveSampleSize() applies to those as well).
//   disambiguated        max_β P(β | H_k) > 0.9: one association history holds more than 0.9 of the weight.
//                        Over a run, the fraction of time steps at which it holds (disambiguatedFraction).
//
// Weights need not be normalised: they are divided by their sum. Negative, non-finite or all-zero weights throw
// InputError. The heaviest component is the first one with the largest weight (input order breaks ties).

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "semslam/geometry/Matrix.h"
#include "semslam/models/HypothesisComponent.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

struct HypothesisMetrics {
  std::size_t components = 0;                  ///< N_k
  std::size_t histories = 0;                   ///< distinct β_1:k
  std::size_t heaviestComponent = 0;           ///< index into the input
  double entropy = std::numeric_limits<double>::quiet_NaN();
  double heaviestAssociationWeight = std::numeric_limits<double>::quiet_NaN();  ///< max_β P(β | H_k)
  bool disambiguated = false;                  ///< heaviestAssociationWeight > threshold
  double ess = std::numeric_limits<double>::quiet_NaN();
  double detCovariance = std::numeric_limits<double>::quiet_NaN();   ///< NaN without a covariance
  double errorHeaviest = std::numeric_limits<double>::quiet_NaN();   ///< x̃^{w_max}; NaN without a true pose
  double errorWeightedAverage = std::numeric_limits<double>::quiet_NaN();  ///< x̃^{w_avg}
};

/// −Σ w log w of the normalised weights (natural log).
double entropy(const std::vector<double>& weights);
/// 1 / Σ w² of the normalised weights.
double effectiveSampleSize(const std::vector<double>& weights);

/// The metrics above at the current time; `truePose` (the true x_k) enables the two errors.
HypothesisMetrics evaluateHypotheses(const std::vector<HypothesisComponent>& components,
                                     const std::optional<Pose>& truePose, double disambiguationThreshold = 0.9);

/// The fraction of time steps whose max_β P(β | H_k) exceeds `threshold` (NaN for no steps).
double disambiguatedFraction(const std::vector<double>& heaviestAssociationWeights, double threshold = 0.9);

}  // namespace semslam
