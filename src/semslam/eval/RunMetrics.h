#pragma once
// RunMetrics: everything one run of one method is scored by. Every method (paper A's
// hybrid belief, paper B's five strategies, any later one) writes the same schema, so runs can be compared and
// aggregated by one script. docs/metrics.md documents every field: definition, units, conventions.
//
// In memory, a field that does not apply to a run (hybrid-belief metrics for paper B's methods, data association
// accuracy without detection ground truth, NEES without covariances) is NaN (numbers), std::nullopt (counts) or
// an empty `alignment`; in the file it is `null`. Non-finite numbers are written as `null` too (JSON has no NaN).
// `method` is always a string (possibly empty).
// Its file, metrics.json, is io/RunMetricsFile.h's.

#include <limits>
#include <optional>
#include <string>

namespace semslam {

struct RunMetrics {
  static constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

  std::string method;                  ///< "method": e.g. "hybrid", "mm+nh"
  std::optional<long long> dimension;  ///< "dimension": 2 or 3
  double timeSeconds = kNotApplicable; ///< "time_s": wall-clock time of the estimation (s)

  // Trajectory (TrajectoryMetrics.h): positions after rigid alignment; rotations in radians.
  std::string alignment;               ///< "alignment": "se2" | "se3" | "none"
  std::optional<long long> poses;      ///< "poses": poses compared
  double ateRmse = kNotApplicable, ateMean = kNotApplicable, ateMedian = kNotApplicable, ateMax = kNotApplicable;
  double rotRmse = kNotApplicable, rotMean = kNotApplicable, rotMedian = kNotApplicable, rotMax = kNotApplicable;

  // Data association (DataAssociationAccuracy.h).
  double daAccuracy = kNotApplicable;
  std::optional<long long> daCorrect, daTotal, daNull, daClutter;
  // Association errors by kind (AssociationErrors.h).
  double daAccuracyReal = kNotApplicable;
  double pairwisePrecision = kNotApplicable, pairwiseRecall = kNotApplicable;
  double clutterRejected = kNotApplicable;
  double clutterRejectedMoving = kNotApplicable, clutterRejectedFalsePositive = kNotApplicable;
  std::optional<long long> landmarksMerged, landmarksSplit;
  double realUnassigned = kNotApplicable, realOnAnotherLandmark = kNotApplicable,
         realOnUnmatchedEstimate = kNotApplicable;
  // Decisions on the true history (DecisionAccuracy.h): runs with SemanticSlamOptions::decideOnTrueHistory only.
  double decisionAccuracyReal = kNotApplicable, decisionClutterRejected = kNotApplicable;
  std::optional<long long> decisionsResightingElsewhere, decisionsResightingUnassigned, decisionsFirstSightingForced;

  // Landmarks (LandmarkMetrics.h).
  std::optional<long long> landmarksEstimated, landmarksTrue, landmarkCountError, landmarksMatched;
  double landmarkRmse = kNotApplicable;
  double classAccuracy = kNotApplicable;

  // Consistency (Nees.h).
  double neesMean = kNotApplicable;
  std::optional<long long> neesCount, neesDof;
  double neesLower = kNotApplicable, neesUpper = kNotApplicable;

  // Hybrid belief (HypothesisMetrics.h), at the final time step.
  double entropy = kNotApplicable;
  double detCov = kNotApplicable;
  double errWmax = kNotApplicable;
  double errWavg = kNotApplicable;
  double ess = kNotApplicable;
  double assocWeightMax = kNotApplicable;
  double disambiguatedFraction = kNotApplicable;
  std::optional<long long> components, histories;
};

}  // namespace semslam
