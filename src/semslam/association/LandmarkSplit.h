#pragma once
// LandmarkSplit: whether the detections held by one landmark came from two objects closer together than the sensor
// resolves, told apart by their labels (docs/association-front-end.md §5d). It is the merge test of §5 read
// backwards: the same log-odds of "one object" against "two, the second placed uniformly", evaluated on a
// partition of one landmark's detections instead of on two landmarks.
//
// Data, per detection i on the landmark: its class likelihoods s_i(c) = P(label_i | c) (ClassBelief.h) and, at the
// current estimate with every pose held fixed, its whitened residual e_i and whitened Jacobian J_i with respect to
// the position part of the landmark's tangent (d columns: translation first).
//
// A candidate split (a, b), classes a ≠ b: B = {i : s_i(b) > s_i(a)}, A the rest, both non-empty. Each group's own
// position, poses fixed, is one Gauss-Newton step from the landmark's estimate:
//     I_G = Σ_{i∈G} J_iᵀ J_i,    δ_G = −I_G⁻¹ Σ_{i∈G} J_iᵀ e_i,
// and under "one object" δ_A − δ_B ~ N(0, Σ_d), Σ_d = I_A⁻¹ + I_B⁻¹ (the sensor noise). The labels, under one
// object of unknown class and
// under the uniform class prior:
//     P(s_G) = (1/M) Σ_c Π_{i∈G} s_i(c).
// Two co-located objects would both be in view whenever one is: at each of the n steps with a detection on the
// landmark (at most one per step, exclusion) the other object was missed, probability (1 − P_D) each, where one
// object needs nothing. The log-odds of one object against two, the second an unassigned landmark of density ρ
// (UnassignedHypothesis.h), with the geometry taken where it favours one object most (δ_A = δ_B: the groups' own
// positions come from detections at different poses, whose relative errors the poses-fixed Σ_d leaves out, so
// their difference is not evidence; the labels and the misses decide):
//     score(a, b) = ln N(0; 0, Σ_d) + ln P(s_A∪B) − ln P(s_A) − ln P(s_B) − ln ρ − n ln(1 − P_D).
// (The merge test's class term M Σ_c P(c | A) P(c | B) equals P(s_A∪B) / (P(s_A) P(s_B)) for beliefs built from
// the uniform prior.) The landmark splits along
// the candidate of lowest score when that score is negative; of the two groups, the one holding the first detection
// (the landmark's oldest) stays, the other is "second".
//
// Invariants of the result: `second` has one entry per detection, the first false, at least one true; `score` < 0;
// `secondDelta` is δ_B (d entries) in the landmark's tangent at the estimate.

#include <optional>
#include <vector>

#include "semslam/geometry/Matrix.h"

namespace semslam {

/// One detection on the landmark, linearised with the poses held fixed (see above).
struct SplitEvidence {
  Vector classLikelihoods;  ///< s_i(c), M entries
  Vector whitenedError;     ///< e_i
  Matrix positionJacobian;  ///< J_i: whitened, with respect to the landmark tangent's d position entries
};

struct LandmarkSplitDecision {
  std::vector<bool> second;  ///< per detection: whether it moves to the second object (group B)
  int firstClass = 0;        ///< the most probable class of the detections that stay, argmax_c Π s_i(c)
  int secondClass = 0;       ///< and of those that move
  double score = 0.0;        ///< the log-odds above (< 0)
  Vector secondDelta;        ///< δ_B: the second object's position step from the landmark's estimate
};

/// The detection probability the split test assumes: the least that §5's patience rule is argued for
/// (docs/association-front-end.md §5), so the test charges the fewest misses consistent with it.
inline constexpr double kAssumedDetectionProbability = 0.5;

/// The best split of a landmark's detections, or nullopt when one object explains them at least as well as two
/// (score ≥ 0 for every candidate), when there are fewer than two detections or no labels (M < 2).
/// `logCartesianDensity` is ln ρ, `detectionProbability` P_D. Throws std::invalid_argument for detections of
/// inconsistent sizes or P_D outside [0, 1).
std::optional<LandmarkSplitDecision> bestLandmarkSplit(const std::vector<SplitEvidence>& detections,
                                                       double logCartesianDensity,
                                                       double detectionProbability = kAssumedDetectionProbability);

}  // namespace semslam
