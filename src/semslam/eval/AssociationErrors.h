#pragma once
// Association errors, separated by kind: what a single accuracy number mixes. All are measured over the same
// detections and the same estimated ↔ true landmark matching as DataAssociationAccuracy.h (LandmarkMatching.h), on
// the detections with known truth. A detection is *real* when its truth is a landmark, *clutter* when its truth is
// kNotALandmark; a detection whose truth is kUnknownTruth is neither and enters no count, pair or ratio (docs/
// metrics.md). It is *assigned* when the final estimate puts it on a landmark (a detection on the null
// hypothesis, on a provisional landmark the method dropped, or rejected, is unassigned: the method reports
// std::nullopt for it).
//
//   accuracy_real       (real detections whose estimate the matching pairs with their truth) / (real detections).
//                       An unassigned real detection counts as wrong. NaN without real detections.
//                       Example: truths [a a b b], estimates [1 1 1 ∅]; matching 1↔a: 2 correct of 4 → 0.5.
//   pairwise precision  over the unordered pairs of ASSIGNED real detections:
//                         (pairs on the same estimate AND of the same truth) / (pairs on the same estimate);
//                       1 when no two detections of different landmarks share an estimate (no merge).
//   pairwise recall       (pairs on the same estimate AND of the same truth) / (pairs of the same truth);
//                       1 when every landmark's assigned detections sit on one estimate (no split).
//                       Unassigned detections form no pairs; NaN when the denominator is 0.
//                       Example: truths [a a b], estimates [1 1 1]: same-estimate pairs 3, same-truth pairs 1,
//                       both 1 → precision 1/3, recall 1.
//   clutter_rejected    (clutter detections left unassigned) / (clutter detections); NaN without clutter.
//   clutter_rejected_moving          the same over the clutter detections WITH a clutter source (a moving object
//                                    the dataset identifies: a moving KITTI track, another MRCLAM robot);
//   clutter_rejected_false_positive  the same over the clutter detections WITHOUT one (a false positive: nothing
//                                    labelled produced it; every clutter detection of a log that has no sources).
//                       The two partition the clutter, so clutter_rejected is their count-weighted mean; each is
//                       NaN when its part is empty. Example: clutter [source 3 on ∅, source 3 on 1, no source on
//                       ∅] → moving 1/2, false positive 1/1, clutter_rejected 2/3.
//   landmarks_merged    true landmarks t with at least 2, and at least 10 %, of their detections on ONE estimate
//                       that the matching gives to ANOTHER true landmark (t was merged into it).
//   landmarks_split     true landmarks t with at least 2, and at least 10 %, of their detections on ONE estimate
//                       that the matching gives to NO true landmark (a second estimate of t).
//                       Detections scattered one by one over several estimates are neither.
//                       Examples: truths [a a a b b] on estimates [1 1 1 1 1]: the matching gives 1 to a (3
//                       shared), b has 2 of 2 detections on a's estimate → merged = 1. Truths [a a a a a] on
//                       estimates [1 1 1 2 2]: 1 ↔ a, 2 is matched to nothing, a has 2 of 5 on it → split = 1.
// The 10 % share is of all the landmark's real detections (assigned or not).
//   Where the real detections that accuracy_real does not count went: three shares of the real detections that,
//   with accuracy_real, sum to 1 (each NaN without real detections).
//   real_unassigned             on no landmark (the null hypothesis, a dropped provisional landmark, rejected);
//   real_on_another_landmark    on an estimate the matching gives to another true landmark (the kind of error
//                               landmarks_merged counts landmark by landmark);
//   real_on_unmatched_estimate  on an estimate the matching gives to no true landmark: a second estimate of their
//                               object (the kind landmarks_split counts), or one that holds mostly clutter.
//                       Example: truths [a a a a b b c] on estimates [1 1 1 2 1 ∅ 3]: the matching gives 1 to
//                       a (3 shared) and 3 to c; correct a a a and c (accuracy_real 4/7); a on 2 (unmatched) 1/7,
//                       b on 1 (a's) 1/7, b on ∅ 1/7.

#include <cstddef>
#include <limits>
#include <vector>

#include "semslam/eval/LandmarkMatching.h"

namespace semslam {

struct AssociationErrors {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  double accuracyReal = kNaN;
  std::size_t realCorrect = 0;
  std::size_t realTotal = 0;

  double pairwisePrecision = kNaN;
  double pairwiseRecall = kNaN;
  std::size_t pairsSameEstimate = 0;   ///< pairs of assigned real detections on one estimate
  std::size_t pairsSameTruth = 0;      ///< pairs of assigned real detections of one true landmark
  std::size_t pairsBoth = 0;           ///< pairs that are both

  double clutterRejected = kNaN;
  std::size_t clutter = 0;
  std::size_t clutterUnassigned = 0;
  double clutterRejectedMoving = kNaN;         ///< over clutter with a source (DetectionAssociation::clutterSource)
  std::size_t clutterMoving = 0;
  std::size_t clutterMovingUnassigned = 0;
  double clutterRejectedFalsePositive = kNaN;  ///< over clutter without a source
  std::size_t clutterFalsePositive = 0;
  std::size_t clutterFalsePositiveUnassigned = 0;

  std::size_t landmarksMerged = 0;
  std::size_t landmarksSplit = 0;

  double realUnassigned = kNaN;           ///< shares of realTotal (header comment); with accuracyReal they sum to 1
  double realOnAnotherLandmark = kNaN;
  double realOnUnmatchedEstimate = kNaN;
  std::size_t realUnassignedCount = 0;
  std::size_t realOnAnotherLandmarkCount = 0;
  std::size_t realOnUnmatchedEstimateCount = 0;
};

/// The share of a landmark's detections above which a merge or split counts (with at least kMinimumDetections).
inline constexpr double kMergeSplitShare = 0.1;
inline constexpr std::size_t kMergeSplitMinimumDetections = 2;

/// Evaluates `detections` through `matching` (matchLandmarks(detections)).
AssociationErrors evaluateAssociationErrors(const std::vector<DetectionAssociation>& detections,
                                            const LandmarkMatching& matching);

}  // namespace semslam
