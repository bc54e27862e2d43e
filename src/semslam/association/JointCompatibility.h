#pragma once
// JointCompatibility: the most likely association of one step's detections scored by the joint density of their
// innovations, which share the pose's error (docs/association-front-end.md §4, "Joint compatibility"; Neira and
// Tardós 2001, joint compatibility branch and bound).
//
// Each detection i (a row) takes one landmark j of its candidates C_i (a column), no landmark twice (exclusion),
// or stays unassigned. The score of an assignment A, with P the rows it pairs, is
//
//     ln p(A) = Σ_{i ∉ P} u_i + Σ_{i ∈ P} s_{i,A(i)} + ln N(ν_P; 0, S_P),
//
// u_i the unassigned hypothesis's log-likelihood (§1, its label's prior included), s_ij = ln P(s_i | j) the label's
// predictive under landmark j's class belief, and N(ν_P; 0, S_P) the linearised joint density of the stacked
// innovations of the pairings (MarginalLikelihood.h: S_P = H Σ Hᵀ + R over the pose and the paired landmarks). The
// independent score, the Hungarian assignment's (SemanticSlam::independentAssignment), takes Π_i N(ν_i; 0, S_i)
// instead, which counts the pose's uncertainty once per pairing: under a broad prediction each re-sighting alone
// loses to the unassigned hypothesis while two together, whose innovations agree on one pose correction, win.
// An assignment is admissible when its pairings pass the joint gate of §3 stacked, χ²_P − 2 Σ_{i ∈ P} ln(P(s_i | j) /
// P₀(s_i)) at most the gate's χ² quantile at the stacked dimension (χ²_P the stacked innovation's; P₀ the label's
// predictive under the uniform class prior), as must each prefix of them met on the way (JCBB's joint
// compatibility). For one pairing it is the front end's own gate, so that a single detection's options are those
// of the independent score.
//
// Search: depth first over the rows in order, each row's options (unassigned, or a candidate) in the order of their
// likelihood alone (u_i, or s_ij plus the pairing's own density, as the front end weighed it: the row's
// pairingLogLikelihoods; the order decides which of equal scores is found first and how soon the bound cuts, never
// the maximum), so that good assignments are found early; a
// branch is cut when its pairings fail the joint gate, or when its score plus an upper bound on the rows left cannot
// beat the best assignment found so far (the incumbent: the given assignment, where admissible). The bound of row i is
// max(u_i, max_j s_ij − n_i), n_i = ½ m ln 2π + ½ ln det R_i its detection's log-normaliser: each pairing multiplies
// the joint density by a conditional Gaussian density whose covariance is at least R_i, at most exp(−n_i). Ties keep
// the incumbent, then the first found: the result is deterministic. Exact (the maximum over every admissible
// exclusive assignment) unless more than `maximumEvaluations` joint densities are needed; then the best found so
// far is returned and `exhaustive` is false.

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/MarginalLikelihood.h"

namespace semslam {

/// One detection of the step.
struct JointAssignmentRow {
  std::vector<int> candidates;                ///< the landmarks (columns) it may take
  std::vector<double> labelLogLikelihoods;    ///< s_ij, one per candidate
  std::vector<double> pairingLogLikelihoods;  ///< s_ij + ln N(ν_ij; 0, S_ij), each pairing alone: the order tried
  double unassignedLogLikelihood = 0.0;       ///< u_i
  double labelPriorLogLikelihood = 0.0;       ///< ln P₀(s_i), the label under the uniform class prior (the gate's)
  double logNormalizer = 0.0;                 ///< n_i
};

/// The linearised joint density of the pairings (row, landmark), rows ascending: ln N(ν_P; 0, S_P), its χ² and
/// stacked dimension.
using JointDensity = std::function<LinearizedLikelihood(const std::vector<std::pair<std::size_t, int>>& pairings)>;

struct JointAssignment {
  std::vector<int> landmarkOfRow;  ///< per row: the landmark, or −1 for unassigned
  double logLikelihood = 0.0;      ///< ln p(A) above
  bool exhaustive = true;          ///< false where the evaluation budget ran out
  long evaluations = 0;            ///< joint densities computed
};

/// The budget of jointlyCompatibleAssignment: far above what a step of the logs needs (docs/association-front-end.md
/// §4), small enough that a step with many ambiguous detections stays within milliseconds.
inline constexpr long kDefaultJointEvaluations = 20000;

/// The admissible exclusive assignment of the largest joint score (above). `incumbent` (one entry per row, −1 or a
/// candidate of the row) seeds the search. Throws std::invalid_argument for inconsistent sizes, an incumbent
/// outside its row's candidates or taking a landmark twice, or a non-positive budget.
JointAssignment jointlyCompatibleAssignment(const std::vector<JointAssignmentRow>& rows, const JointDensity& density,
                                            const AssociationGate& gate, const std::vector<int>& incumbent,
                                            long maximumEvaluations = kDefaultJointEvaluations);

}  // namespace semslam
