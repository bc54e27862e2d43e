#include "semslam/eval/Alignment.h"

#include "semslam/core/InputError.h"

namespace semslam {

namespace {

SE3 rigid(const Matrix3& rotation, const Vector3& translation) { return SE3(SO3(rotation), translation); }

}  // namespace

AlignmentMode parseAlignmentMode(const std::string& name) {
  if (name == "none") return AlignmentMode::None;
  if (name == "se3") return AlignmentMode::Se3;
  if (name == "sim3") return AlignmentMode::Sim3;
  if (name == "scale") return AlignmentMode::Scale;
  if (name == "origin") return AlignmentMode::Origin;
  throw InputError("unknown alignment '" + name + "' (expected none, se3, sim3, scale or origin)");
}

std::string toString(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::None: return "none";
    case AlignmentMode::Se3: return "se3";
    case AlignmentMode::Sim3: return "sim3";
    case AlignmentMode::Scale: return "scale";
    case AlignmentMode::Origin: return "origin";
  }
  return "unknown";
}

SimilarityTransform alignTrajectory(Trajectory& estimate, const Trajectory& reference, AlignmentMode mode) {
  if (estimate.size() != reference.size()) {
    throw InputError("alignment: estimate has " + std::to_string(estimate.size()) + " poses, reference has " +
                     std::to_string(reference.size()) + " (associate them first)");
  }
  if (mode == AlignmentMode::None) return {};
  if (estimate.empty()) throw InputError("alignment: no poses");

  SimilarityTransform applied;
  switch (mode) {
    case AlignmentMode::Se3:
    case AlignmentMode::Sim3:
    case AlignmentMode::Scale: {
      const bool withScale = mode != AlignmentMode::Se3;
      const SimilarityTransform s = umeyamaAlignment(estimate.positions(), reference.positions(), withScale);
      if (withScale) estimate.scale(s.scale);
      if (mode == AlignmentMode::Scale) {
        applied.scale = s.scale;
      } else {
        estimate.transform(rigid(s.rotation, s.translation));
        applied = s;
      }
      break;
    }
    case AlignmentMode::Origin: {
      const SE3 toReference = reference.pose(0) * estimate.pose(0).inverse();
      estimate.transform(toReference);
      applied.rotation = toReference.rotation().matrix();
      applied.translation = toReference.translation();
      break;
    }
    case AlignmentMode::None:
      break;
  }
  return applied;
}

}  // namespace semslam
