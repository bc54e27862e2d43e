#include "semslam/eval/AssociationErrors.h"

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
  std::map<int, std::size_t> perEstimate, perTruthAssigned, perTruth, mergedOf, splitOf;
  for (const DetectionAssociation& d : detections) {
    if (d.truth == kNotALandmark) {
      ++errors.clutter;
      if (!d.estimate) ++errors.clutterUnassigned;
      continue;
    }
    ++errors.realTotal;
    ++perTruth[d.truth];
    if (!d.estimate) continue;
    const std::optional<int> matched = matching.truthOf(*d.estimate);
    if (matched == d.truth) ++errors.realCorrect;
    else if (matched) ++mergedOf[d.truth];
    else ++splitOf[d.truth];
    ++perEstimateAndTruth[{*d.estimate, d.truth}];
    ++perEstimate[*d.estimate];
    ++perTruthAssigned[d.truth];
  }
  errors.accuracyReal = ratio(errors.realCorrect, errors.realTotal);
  errors.clutterRejected = ratio(errors.clutterUnassigned, errors.clutter);

  for (const auto& [key, n] : perEstimateAndTruth) errors.pairsBoth += pairsOf(n);
  for (const auto& [estimate, n] : perEstimate) errors.pairsSameEstimate += pairsOf(n);
  for (const auto& [truth, n] : perTruthAssigned) errors.pairsSameTruth += pairsOf(n);
  errors.pairwisePrecision = ratio(errors.pairsBoth, errors.pairsSameEstimate);
  errors.pairwiseRecall = ratio(errors.pairsBoth, errors.pairsSameTruth);

  for (const auto& [truth, n] : mergedOf) {
    if (substantial(n, perTruth[truth])) ++errors.landmarksMerged;
  }
  for (const auto& [truth, n] : splitOf) {
    if (substantial(n, perTruth[truth])) ++errors.landmarksSplit;
  }
  return errors;
}

}  // namespace semslam
