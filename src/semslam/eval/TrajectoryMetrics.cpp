#include "semslam/eval/TrajectoryMetrics.h"

#include <cmath>

#include "semslam/eval/PlanarAlignment.h"
#include "semslam/eval/PoseRelation.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

template <class PoseType>
void checkSizes(const std::vector<PoseType>& estimate, const std::vector<PoseType>& reference) {
  if (estimate.size() != reference.size()) {
    throw InputError("trajectory errors: the estimate has " + std::to_string(estimate.size()) +
                     " poses, the reference " + std::to_string(reference.size()));
  }
  if (estimate.empty()) throw InputError("trajectory errors: no poses");
}

template <class PoseType>
std::vector<PoseType> posesOf(const std::vector<Pose>& poses, const char* what) {
  std::vector<PoseType> out;
  out.reserve(poses.size());
  for (const Pose& pose : poses) {
    const PoseType* p = std::get_if<PoseType>(&pose);
    if (p == nullptr) throw InputError(std::string("trajectory errors: mixed 2D and 3D poses in the ") + what);
    out.push_back(*p);
  }
  return out;
}

/// The translations of `poses` as the columns of a D×n matrix, in order.
template <int D, class PoseType>
Eigen::Matrix<double, D, Eigen::Dynamic> positionColumns(const std::vector<PoseType>& poses) {
  Eigen::Matrix<double, D, Eigen::Dynamic> columns(D, static_cast<Eigen::Index>(poses.size()));
  for (std::size_t i = 0; i < poses.size(); ++i) columns.col(static_cast<Eigen::Index>(i)) = poses[i].translation();
  return columns;
}

void summarise(TrajectoryErrors& result) {
  result.translation = computeErrorStatistics(result.translationErrors);
  result.rotation = computeErrorStatistics(result.rotationErrors);
}

}  // namespace

SimilarityTransform alignPlanarTrajectory(const std::vector<SE2>& estimate, const std::vector<SE2>& reference) {
  checkSizes(estimate, reference);
  return planarRigidAlignment(positionColumns<2>(estimate), positionColumns<2>(reference));
}

SimilarityTransform alignSpatialTrajectory(const std::vector<SE3>& estimate, const std::vector<SE3>& reference) {
  checkSizes(estimate, reference);
  return umeyamaAlignment(positionColumns<3>(estimate), positionColumns<3>(reference), false);
}

TrajectoryErrors evaluateTrajectoryErrors(const std::vector<SE2>& estimate, const std::vector<SE2>& reference,
                                          bool align) {
  checkSizes(estimate, reference);
  TrajectoryErrors result;
  result.dimension = 2;
  result.aligned = align;
  if (align) result.alignment = alignPlanarTrajectory(estimate, reference);
  const Matrix2 rotation = result.alignment.rotation.topLeftCorner<2, 2>();
  const Vector2 translation = result.alignment.translation.head<2>();
  const SO2 turn = SO2::fromCosSin(rotation(0, 0), rotation(1, 0));
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const Point2 p = rotation * estimate[i].translation() + translation;
    result.translationErrors.push_back((p - reference[i].translation()).norm());
    result.rotationErrors.push_back(std::abs(reference[i].rotation().between(turn * estimate[i].rotation()).theta()));
  }
  summarise(result);
  return result;
}

TrajectoryErrors evaluateTrajectoryErrors(const std::vector<SE3>& estimate, const std::vector<SE3>& reference,
                                          bool align) {
  checkSizes(estimate, reference);
  TrajectoryErrors result;
  result.dimension = 3;
  result.aligned = align;
  if (align) result.alignment = alignSpatialTrajectory(estimate, reference);
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const Point3 p = result.alignment.rotation * estimate[i].translation() + result.alignment.translation;
    result.translationErrors.push_back((p - reference[i].translation()).norm());
    const Matrix3 error =
        reference[i].rotation().matrix().transpose() * result.alignment.rotation * estimate[i].rotation().matrix();
    result.rotationErrors.push_back(rotationAngle(error));
  }
  summarise(result);
  return result;
}

TrajectoryErrors evaluateTrajectoryErrors(const std::vector<Pose>& estimate, const std::vector<Pose>& reference,
                                          bool align) {
  if (estimate.empty() || reference.empty()) checkSizes(estimate, reference);
  if (std::holds_alternative<SE2>(estimate.front())) {
    return evaluateTrajectoryErrors(posesOf<SE2>(estimate, "estimate"), posesOf<SE2>(reference, "reference"), align);
  }
  return evaluateTrajectoryErrors(posesOf<SE3>(estimate, "estimate"), posesOf<SE3>(reference, "reference"), align);
}

}  // namespace semslam
