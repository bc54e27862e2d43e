#include "semslam/eval/RelativePoseError.h"

#include "semslam/core/InputError.h"

namespace semslam {

RelativePoseErrors relativePoseErrors(const Trajectory& reference, const Trajectory& estimate,
                                      const RelativePoseErrorOptions& options) {
  if (reference.size() != estimate.size()) {
    throw InputError("RPE: reference has " + std::to_string(reference.size()) + " poses, estimate has " +
                     std::to_string(estimate.size()) + " (associate them first)");
  }
  RelativePoseErrors result;
  result.pairs = selectPosePairs(options.pairsFromReference ? reference : estimate, options.delta, options.unit,
                                 options.allPairs, options.relativeTolerance);
  result.errors.reserve(result.pairs.size());
  for (const auto& [i, j] : result.pairs) {
    const SE3 referenceMotion = reference.pose(i).between(reference.pose(j));
    const SE3 estimateMotion = estimate.pose(i).between(estimate.pose(j));
    result.errors.push_back(poseErrorValue(referenceMotion.between(estimateMotion).matrix(), options.relation));
  }
  return result;
}

}  // namespace semslam
