#pragma once
// One weighted hypothesis of a hybrid belief (paper A, Tchuiev, Feldman, Indelman): a realization of the object
// classes C and of the data-association history β_1:k, with the Gaussian belief of the current pose under it.
// The hybrid estimator (hybrid/) produces these; the hypothesis metrics (eval/HypothesisMetrics.h) score them.
//
// Marginals of a belief given as components (weights need not be normalised: they are divided by their sum):
//   association marginal (A, eq. 8)   P(β_1:k | H_k) = Σ_C w^C_β1:k   (weights of components with the same
//                                     history summed over class realizations)
//   class marginal       (A, eq. 7)   P(C | H_k) = Σ_β w^C_β; per object j: P(c_j = m) = Σ_{C: C_j = m} w
// Negative, non-finite or all-zero weights throw InputError.

#include <optional>
#include <vector>

#include "semslam/geometry/Matrix.h"
#include "semslam/models/AssociationHistory.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// One component of a hybrid belief at the current time k.
struct HypothesisComponent {
  double weight = 0.0;               ///< w^C_β1:k (any positive scale)
  AssociationHistory associations;   ///< β_1:k
  std::vector<int> classes;          ///< C: the class of each object (index j), in [0, M)
  Pose pose = SE2();                 ///< mean of the current pose x_k
  Matrix covariance;                 ///< covariance of x_k (right perturbation, translation first)
};

struct AssociationHypothesis {
  AssociationHistory associations;
  double weight = 0.0;             ///< P(β_1:k | H_k)
  std::size_t firstComponent = 0;  ///< the first component (input order) with this history
};

/// The components' weights, in order.
std::vector<double> componentWeights(const std::vector<HypothesisComponent>& components);
/// w_i / Σ w; throws InputError for an empty vector, negative or non-finite weights, or a zero sum.
std::vector<double> normalizeWeights(const std::vector<double>& weights);

/// Eq. 8: the association marginal, heaviest first (ties: in the order of their first components). O(C) for
/// histories that share nodes (AssociationHistory.h), hashed otherwise.
std::vector<AssociationHypothesis> associationMarginal(const std::vector<HypothesisComponent>& components);
/// Eq. 7 per object: row j holds P(c_j = m), m = 0..classes−1. Every component must have the same number of
/// objects, with classes in [0, classes).
Matrix classMarginals(const std::vector<HypothesisComponent>& components, int classes);

}  // namespace semslam
