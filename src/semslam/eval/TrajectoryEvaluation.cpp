#include "semslam/eval/TrajectoryEvaluation.h"

#include "semslam/eval/AbsolutePoseError.h"
#include "semslam/eval/Association.h"

namespace semslam {

namespace {

/// Steps 1 and 2: the associated reference and the associated, aligned estimate.
AssociatedTrajectories associateAndAlign(const Trajectory& reference, const Trajectory& estimate,
                                         const EvaluationOptions& options, EvaluationResult& result) {
  AssociatedTrajectories associated =
      associateTrajectories(reference, estimate, options.maxTimeDifference, options.timeOffset);
  result.associatedPoses = associated.reference.size();
  result.alignment = alignTrajectory(associated.estimate, associated.reference, options.alignment);
  return associated;
}

}  // namespace

EvaluationResult evaluateAbsolutePoseError(const Trajectory& reference, const Trajectory& estimate,
                                           const EvaluationOptions& options) {
  EvaluationResult result;
  const AssociatedTrajectories data = associateAndAlign(reference, estimate, options, result);
  result.errors = absolutePoseErrors(data.reference, data.estimate, options.relation);
  result.statistics = computeErrorStatistics(result.errors);
  return result;
}

EvaluationResult evaluateRelativePoseError(const Trajectory& reference, const Trajectory& estimate,
                                           const EvaluationOptions& options) {
  EvaluationResult result;
  const AssociatedTrajectories data = associateAndAlign(reference, estimate, options, result);
  RelativePoseErrorOptions rpe;
  rpe.relation = options.relation;
  rpe.delta = options.delta;
  rpe.unit = options.deltaUnit;
  rpe.allPairs = options.allPairs;
  rpe.relativeTolerance = options.relativeDeltaTolerance;
  rpe.pairsFromReference = options.pairsFromReference;
  RelativePoseErrors errors = relativePoseErrors(data.reference, data.estimate, rpe);
  result.rpePairs = std::move(errors.pairs);
  result.errors = std::move(errors.errors);
  result.statistics = computeErrorStatistics(result.errors);
  return result;
}

}  // namespace semslam
