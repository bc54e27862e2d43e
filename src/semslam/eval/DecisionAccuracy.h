#pragma once
// DecisionAccuracy: how often paper B's front end decides a detection right when every earlier association was right
// (SemanticSlamOptions::decideOnTrueHistory, docs/association-front-end.md §8b): its decisions one step at a time,
// with no error of its own to build on. Not a bound on a run's own da_accuracy_real: a run repairs some decisions
// later (a provisional landmark merged into the one it should have been, a mixture that switches), and loses
// others to the lifecycle (a stream of clutter confirming a landmark of its own, which a true history never has).
//
// Each scored detection (a true landmark or clutter; kUnknownTruth is left out, as everywhere: docs/metrics.md)
// carries the front end's decision d (a landmark, or unassigned) and the landmark the true history had for its
// object at that step, ℓ (none for clutter and for an object not mapped before the step). The decision is right
// when d = ℓ:
//   - a re-sighting (ℓ a landmark) is right on ℓ, wrong on another landmark ("elsewhere") or unassigned;
//   - a first sighting (ℓ none, a true landmark) is right unassigned, wrong on any landmark ("forced");
//   - clutter is rejected when unassigned.
//   accuracyReal     = right decisions of true-landmark detections / true-landmark detections
//   clutterRejected  = clutter decided unassigned / clutter detections
// Example: re-sightings of a on a, of a on b, of b unassigned, a first sighting of c unassigned, one clutter
// detection on a: accuracyReal 2/4 (elsewhere 1, unassigned 1), clutterRejected 0/1. Either fraction is NaN
// (RunMetrics::kNotApplicable) when it has no detection.

#include <cstddef>
#include <vector>

#include "semslam/models/RunResult.h"

namespace semslam {

/// A scored detection (truth ≥ 0 or kNotALandmark) with the decision taken on it.
struct ScoredDecision {
  int truth = kNotALandmark;
  HistoryDecision decision;
};

struct DecisionAccuracy {
  std::size_t realTotal = 0, realCorrect = 0;
  std::size_t resightingsElsewhere = 0;    ///< a re-sighting decided onto another landmark
  std::size_t resightingsUnassigned = 0;   ///< a re-sighting decided unassigned
  std::size_t firstSightingsForced = 0;    ///< a first sighting decided onto a mapped landmark
  std::size_t clutterTotal = 0, clutterRejected = 0;
  double accuracyReal = 0.0;               ///< NaN without true-landmark detections
  double clutterRejectedFraction = 0.0;    ///< NaN without clutter
};

/// The fractions and counts above. Throws std::invalid_argument for a truth that is neither a landmark id (≥ 0) nor
/// kNotALandmark, and for clutter whose `right` is a landmark (clutter has none).
DecisionAccuracy evaluateDecisions(const std::vector<ScoredDecision>& decisions);

}  // namespace semslam
