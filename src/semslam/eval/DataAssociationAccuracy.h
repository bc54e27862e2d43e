#pragma once
// Data association accuracy: the fraction of detections whose association in the final estimate is correct,
// judged through the landmark matching of LandmarkMatching.h (estimated ids are arbitrary names; the matching says
// which true landmark each stands for).
//
// For a detection with truth t (a landmark id, or kNotALandmark for clutter) and estimate e (an estimated landmark
// id, or the null hypothesis ∅):
//   t = clutter,   e = ∅        correct   (the clutter was rejected)
//   t = clutter,   e = a landmark  wrong   (clutter associated with, or creating, a landmark)
//   t = landmark,  e = ∅        wrong     (a real detection thrown away)
//   t = landmark,  e = a landmark  correct iff the matching pairs e with t
//
//   accuracy = correct / total          (NaN when there is no detection)
//
// Hence accuracy = (Σ_matched shared detections + clutter detections given ∅) / total: it is invariant under any
// renaming of the estimated landmarks, a landmark split in two gets credit for its larger part only, and two true
// landmarks merged into one estimated landmark get credit for one of them.
// Only detections with known truth enter (leave out detections whose truth id is absent from the log); a
// detection whose truth is kUnknownTruth (the dataset cannot decide: docs/metrics.md) is left out here too, so it
// changes no count and no ratio.

#include <cstddef>
#include <limits>
#include <vector>

#include "semslam/eval/LandmarkMatching.h"

namespace semslam {

struct DataAssociationAccuracy {
  double accuracy = std::numeric_limits<double>::quiet_NaN();  ///< correct / total; NaN when total = 0
  std::size_t correct = 0;
  std::size_t total = 0;           ///< detections evaluated
  std::size_t nullChosen = 0;      ///< detections given the null hypothesis (right or wrong)
  std::size_t clutter = 0;         ///< detections whose truth is kNotALandmark
  std::size_t clutterRejected = 0; ///< clutter given the null hypothesis (counted in `correct`)
  LandmarkMatching matching;       ///< the estimated ↔ true landmark matching used
};

/// Evaluates the associations (see the header comment). Throws InputError for a truth id below -2.
DataAssociationAccuracy evaluateDataAssociation(const std::vector<DetectionAssociation>& detections);

}  // namespace semslam
