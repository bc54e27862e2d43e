#include "semslam/eval/AbsolutePoseError.h"

#include "semslam/core/InputError.h"

namespace semslam {

std::vector<double> absolutePoseErrors(const Trajectory& reference, const Trajectory& estimate,
                                       PoseRelation relation) {
  if (reference.size() != estimate.size()) {
    throw InputError("APE: reference has " + std::to_string(reference.size()) + " poses, estimate has " +
                     std::to_string(estimate.size()) + " (associate them first)");
  }
  std::vector<double> errors;
  errors.reserve(reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (relation == PoseRelation::TranslationPart) {
      errors.push_back((estimate.position(i) - reference.position(i)).norm());
    } else {
      errors.push_back(poseErrorValue(estimate.pose(i).between(reference.pose(i)).matrix(), relation));
    }
  }
  return errors;
}

}  // namespace semslam
