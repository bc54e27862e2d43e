#include "semslam/eval/AssociationErrors.h"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include "semslam/models/MeasurementLog.h"

namespace semslam {
namespace {

std::size_t pairsOf(std::size_t n) { return n * (n - 1) / 2; }

double ratio(std::size_t numerator, std::size_t denominator) {
  return denominator > 0 ? static_cast<double>(numerator) / static_cast<double>(denominator) : AssociationErrors::kNaN;
}

/// Whether `count` of a landmark's `total` detections make a merge or a split (header).
bool substantial(std::size_t count, std::size_t total) {
  return count >= kMergeSplitMinimumDetections &&
         static_cast<double>(count) >= kMergeSplitShare * static_cast<double>(total);
}

}  // namespace

AssociationErrors evaluateAssociationErrors(const std::vector<DetectionAssociation>& detections,
                                            const LandmarkMatching& matching) {
  AssociationErrors errors;
  std::map<std::pair<int, int>, std::size_t> perEstimateAndTruth;  // assigned real detections
  std::map<int, std::size_t> perEstimate, perTruthAssigned, perTruth;
  // A true landmark's detections on each estimate that is not its own: matched to another landmark, or to none.
  std::map<std::pair<int, int>, std::size_t> onAnotherLandmarksEstimate, onUnmatchedEstimate;
  for (const DetectionAssociation& d : detections) {
    if (d.truth == kUnknownTruth) continue;  // not scored (header comment)
    if (d.truth == kNotALandmark) {
      ++errors.clutter;
      if (!d.estimate) ++errors.clutterUnassigned;
      if (d.clutterSource) {
        ++errors.clutterMoving;
        if (!d.estimate) ++errors.clutterMovingUnassigned;
      } else {
        ++errors.clutterFalsePositive;
        if (!d.estimate) ++errors.clutterFalsePositiveUnassigned;
      }
      continue;
    }
    ++errors.realTotal;
    ++perTruth[d.truth];
    if (!d.estimate) {
      ++errors.realUnassignedCount;
      continue;
    }
    const std::optional<int> matched = matching.truthOf(*d.estimate);
    if (matched == d.truth) {
      ++errors.realCorrect;
    } else if (matched) {
      ++onAnotherLandmarksEstimate[{d.truth, *d.estimate}];
      ++errors.realOnAnotherLandmarkCount;
    } else {
      ++onUnmatchedEstimate[{d.truth, *d.estimate}];
      ++errors.realOnUnmatchedEstimateCount;
    }
    ++perEstimateAndTruth[{*d.estimate, d.truth}];
    ++perEstimate[*d.estimate];
    ++perTruthAssigned[d.truth];
  }
  errors.accuracyReal = ratio(errors.realCorrect, errors.realTotal);
  errors.realUnassigned = ratio(errors.realUnassignedCount, errors.realTotal);
  errors.realOnAnotherLandmark = ratio(errors.realOnAnotherLandmarkCount, errors.realTotal);
  errors.realOnUnmatchedEstimate = ratio(errors.realOnUnmatchedEstimateCount, errors.realTotal);
  errors.clutterRejected = ratio(errors.clutterUnassigned, errors.clutter);
  errors.clutterRejectedMoving = ratio(errors.clutterMovingUnassigned, errors.clutterMoving);
  errors.clutterRejectedFalsePositive = ratio(errors.clutterFalsePositiveUnassigned, errors.clutterFalsePositive);

  for (const auto& [key, n] : perEstimateAndTruth) errors.pairsBoth += pairsOf(n);
  for (const auto& [estimate, n] : perEstimate) errors.pairsSameEstimate += pairsOf(n);
  for (const auto& [truth, n] : perTruthAssigned) errors.pairsSameTruth += pairsOf(n);
  errors.pairwisePrecision = ratio(errors.pairsBoth, errors.pairsSameEstimate);
  errors.pairwiseRecall = ratio(errors.pairsBoth, errors.pairsSameTruth);

  // A landmark counts once, however many estimates it was merged into or split over (the largest one decides).
  std::map<int, std::size_t> mergedLargest, splitLargest;
  for (const auto& [key, n] : onAnotherLandmarksEstimate) mergedLargest[key.first] = std::max(mergedLargest[key.first], n);
  for (const auto& [key, n] : onUnmatchedEstimate) splitLargest[key.first] = std::max(splitLargest[key.first], n);
  for (const auto& [truth, n] : mergedLargest) {
    if (substantial(n, perTruth[truth])) ++errors.landmarksMerged;
  }
  for (const auto& [truth, n] : splitLargest) {
    if (substantial(n, perTruth[truth])) ++errors.landmarksSplit;
  }
  return errors;
}

}  // namespace semslam
