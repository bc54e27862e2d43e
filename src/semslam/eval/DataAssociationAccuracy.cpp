#include "semslam/eval/DataAssociationAccuracy.h"

#include "semslam/models/MeasurementLog.h"

namespace semslam {

DataAssociationAccuracy evaluateDataAssociation(const std::vector<DetectionAssociation>& detections) {
  DataAssociationAccuracy result;
  result.matching = matchLandmarks(detections);  // validates the truth ids
  for (const DetectionAssociation& d : detections) {
    if (d.truth == kUnknownTruth) continue;  // not scored (header comment)
    ++result.total;
    const bool isClutter = d.truth == kNotALandmark;
    if (isClutter) ++result.clutter;
    if (!d.estimate) {
      ++result.nullChosen;
      if (isClutter) {
        ++result.clutterRejected;
        ++result.correct;
      }
      continue;
    }
    if (isClutter) continue;
    const std::optional<int> matched = result.matching.truthOf(*d.estimate);
    if (matched && *matched == d.truth) ++result.correct;
  }
  if (result.total > 0) result.accuracy = static_cast<double>(result.correct) / static_cast<double>(result.total);
  return result;
}

}  // namespace semslam
