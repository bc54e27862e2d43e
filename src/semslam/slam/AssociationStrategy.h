#pragma once
// The five data-association strategies of paper B's comparison (sec. V), run by one pipeline (SemanticSlam.h):
//
//   known  ground-truth landmark ids from the log (clutter, id kNotALandmark, is dropped): the upper bound;
//   ml     maximum likelihood: one factor to the most likely gated candidate;
//   gpda   soft association re-weighted by expectation-maximisation between optimisations (Bowman et al.,
//          "Probabilistic data association for semantic SLAM", ICRA 2017): one factor per gated candidate, its
//          information scaled by the candidate's association probability, the probabilities recomputed from the
//          current estimate (E-step) and the graph re-optimised (M-step);
//   mm     a semantic max-mixture factor over the gated candidates (B, sec. IV-C);
//   mm-nh  the same plus a null-hypothesis component (B, sec. IV-C).
// A detection that passes no candidate's gate starts a new landmark under every strategy but `known`.

#include <string>
#include <string_view>
#include <vector>

namespace semslam {

enum class AssociationStrategy { Known, MaximumLikelihood, Gpda, MaxMixture, MaxMixtureNullHypothesis };

/// "known", "ml", "gpda", "mm", "mm-nh".
std::string strategyName(AssociationStrategy strategy);
/// The inverse of strategyName; throws std::invalid_argument listing the valid names.
AssociationStrategy parseStrategy(std::string_view name);
/// All five, in the order above.
std::vector<AssociationStrategy> allStrategies();

}  // namespace semslam
