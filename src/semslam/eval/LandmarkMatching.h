#pragma once
// Which estimated landmark is which true landmark: the one-to-one matching of estimated to true landmark ids that
// maximises the number of detections they share. Every landmark metric (data association accuracy, landmark
// RMSE, class accuracy) is measured through it, so renaming the estimated landmarks changes nothing.
//
// Input: per detection with ground truth, the pair (truth, estimate):
//   truth     the true landmark id (≥ 0), or kNotALandmark (models/MeasurementLog.h) for clutter; kUnknownTruth
//             (the dataset cannot decide) is accepted and left out, exactly as a detection without truth;
//   estimate  the id of the estimated landmark the final estimate associates the detection with, or std::nullopt
//             for the null hypothesis (the detection explains no landmark). A detection that created a landmark
//             is associated with that landmark.
//
// Matching: rows are the distinct estimated ids, columns the distinct true ids (clutter excluded), both in
// ascending order; the weight of (e, t) is the number of detections with estimate e and truth t. The maximum-weight
// one-to-one assignment (solve/HungarianAssignment.h) is computed and only pairs that share at least one detection are
// kept: an estimated landmark that shares no detection with its assigned true landmark is unmatched. On ties the
// assignment that is lexicographically smallest in (ascending estimated id → ascending true id) is taken, so the
// result is deterministic; the number of shared detections in matched pairs (the maximum) does not depend on it.

#include <cstddef>
#include <optional>
#include <vector>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// One detection's true and estimated association (see above).
struct DetectionAssociation {
  int truth = kNotALandmark;    ///< true landmark id ≥ 0, kNotALandmark for clutter, kUnknownTruth (left out)
  std::optional<int> estimate;  ///< estimated landmark id, or std::nullopt for the null hypothesis
  /// Clutter only: the non-landmark object that produced it (Detection::clutterSource: a moving KITTI track, an
  /// MRCLAM robot), or std::nullopt for a false positive. Used by AssociationErrors.h's clutter split only.
  std::optional<int> clutterSource;
};

struct LandmarkPair {
  int estimated = 0;
  int truth = 0;
  std::size_t sharedDetections = 0;
};

struct LandmarkMatching {
  std::vector<LandmarkPair> pairs;  ///< sorted by estimated id; every pair shares ≥ 1 detection

  /// The true id matched to an estimated id, if any.
  std::optional<int> truthOf(int estimated) const;
  /// The estimated id matched to a true id, if any.
  std::optional<int> estimateOf(int truth) const;
  /// Σ shared detections over the matched pairs.
  std::size_t sharedDetections() const;
};

/// The matching of the estimated landmarks that occur in `detections` to the true landmarks that occur there.
/// Throws InputError for a truth id below -2 (kUnknownTruth).
LandmarkMatching matchLandmarks(const std::vector<DetectionAssociation>& detections);

}  // namespace semslam
