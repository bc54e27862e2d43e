#pragma once
// The whole evaluation of an estimated trajectory against a reference, in evo's order (evo_ape / evo_rpe):
//   1. associate by timestamp (Association.h; max difference 0.01 s, offset 0 by default), or by index when a
//      trajectory has no timestamps;
//   2. align the estimate to the reference (Alignment.h; none by default, as evo);
//   3. APE (AbsolutePoseError.h) or RPE (RelativePoseError.h) errors for the chosen pose relation;
//   4. statistics max, mean, median, min, rmse, sse, std (ErrorStatistics.h).
// Every problem with the inputs (no match, too few poses, a degenerate alignment, no RPE pair) throws InputError.

#include <cstddef>
#include <vector>

#include "semslam/eval/Alignment.h"
#include "semslam/eval/ErrorStatistics.h"
#include "semslam/eval/RelativePoseError.h"
#include "semslam/models/Trajectory.h"

namespace semslam {

struct EvaluationOptions {
  PoseRelation relation = PoseRelation::TranslationPart;
  AlignmentMode alignment = AlignmentMode::None;
  double maxTimeDifference = 0.01;  ///< s, evo's --t_max_diff
  double timeOffset = 0.0;          ///< s, added to the estimate's stamps (evo's --t_offset)
  // RPE only (see RelativePoseErrorOptions):
  double delta = 1.0;
  DeltaUnit deltaUnit = DeltaUnit::Frames;
  bool allPairs = false;
  double relativeDeltaTolerance = 0.1;
  bool pairsFromReference = false;
};

struct EvaluationResult {
  ErrorStatistics statistics;
  std::vector<double> errors;      ///< one per compared pose (APE) or pose pair (RPE)
  std::vector<PosePair> rpePairs;  ///< RPE: the compared pairs (indices into the associated trajectories)
  std::size_t associatedPoses = 0; ///< poses left after association
  SimilarityTransform alignment;   ///< what was applied to the estimate (identity for none)
};

EvaluationResult evaluateAbsolutePoseError(const Trajectory& reference, const Trajectory& estimate,
                                           const EvaluationOptions& options = {});
EvaluationResult evaluateRelativePoseError(const Trajectory& reference, const Trajectory& estimate,
                                           const EvaluationOptions& options = {});

}  // namespace semslam
