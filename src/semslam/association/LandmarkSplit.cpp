#include "semslam/association/LandmarkSplit.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/Cholesky>

namespace semslam {
namespace {

constexpr double kNegativeInfinity = -std::numeric_limits<double>::infinity();

/// A group's labels: ln P(s_G) = ln((1/M) Σ_c Π_{i∈G} s_i(c)) (log-sum-exp over c) and the class of highest
/// posterior, argmax_c Π_{i∈G} s_i(c).
struct GroupLabels {
  double logEvidence = kNegativeInfinity;
  int mostProbableClass = 0;
};
/// Over the detections with member[i] == inGroup.
GroupLabels groupLabels(const std::vector<SplitEvidence>& detections, const std::vector<bool>& member, bool inGroup) {
  const Eigen::Index classes = detections.front().classLikelihoods.size();
  Vector logProducts = Vector::Zero(classes);
  for (std::size_t i = 0; i < detections.size(); ++i) {
    if (member[i] != inGroup) continue;
    logProducts += detections[i].classLikelihoods.array().log().matrix();
  }
  Eigen::Index mostProbable = 0;
  const double largest = logProducts.maxCoeff(&mostProbable);
  if (!std::isfinite(largest)) return {};  // no class explains every label of the group
  return {largest + std::log((logProducts.array() - largest).exp().sum()) - std::log(static_cast<double>(classes)),
          static_cast<int>(mostProbable)};
}

/// The group's Gauss-Newton step δ_G and its information I_G (poses fixed); nullopt when I_G is singular.
struct GroupFit {
  Vector delta;
  Matrix covariance;  // I_G⁻¹
};
std::optional<GroupFit> fitGroup(const std::vector<SplitEvidence>& detections, const std::vector<bool>& member,
                                 bool inGroup) {
  const Eigen::Index d = detections.front().positionJacobian.cols();
  Matrix information = Matrix::Zero(d, d);
  Vector gradient = Vector::Zero(d);
  for (std::size_t i = 0; i < detections.size(); ++i) {
    if (member[i] != inGroup) continue;
    information += detections[i].positionJacobian.transpose() * detections[i].positionJacobian;
    gradient += detections[i].positionJacobian.transpose() * detections[i].whitenedError;
  }
  const Eigen::LLT<Matrix> cholesky(information);
  if (cholesky.info() != Eigen::Success) return std::nullopt;
  const Matrix covariance = cholesky.solve(Matrix::Identity(d, d));
  if (!covariance.allFinite()) return std::nullopt;
  return GroupFit{-cholesky.solve(gradient), covariance};
}

/// ln N(x; 0, Σ); nullopt when Σ is not positive definite.
std::optional<double> logGaussianAtZeroMean(const Vector& x, const Matrix& covariance) {
  const Eigen::LLT<Matrix> cholesky(covariance);
  if (cholesky.info() != Eigen::Success) return std::nullopt;
  const double chi2 = cholesky.matrixL().solve(x).squaredNorm();
  const double logDeterminantHalf = cholesky.matrixLLT().diagonal().array().log().sum();
  return -0.5 * chi2 - 0.5 * static_cast<double>(x.size()) * std::log(2.0 * std::numbers::pi) - logDeterminantHalf;
}

}  // namespace

std::optional<LandmarkSplitDecision> bestLandmarkSplit(const std::vector<SplitEvidence>& detections,
                                                       double logCartesianDensity, double detectionProbability) {
  if (!(detectionProbability >= 0.0 && detectionProbability < 1.0)) {
    throw std::invalid_argument("bestLandmarkSplit: the detection probability must be in [0, 1)");
  }
  if (detections.size() < 2) return std::nullopt;
  const Eigen::Index classes = detections.front().classLikelihoods.size();
  const Eigen::Index d = detections.front().positionJacobian.cols();
  for (const SplitEvidence& detection : detections) {
    if (detection.classLikelihoods.size() != classes || detection.positionJacobian.cols() != d ||
        detection.positionJacobian.rows() != detection.whitenedError.size() || d < 1) {
      throw std::invalid_argument("bestLandmarkSplit: detections of inconsistent sizes");
    }
  }
  if (classes < 2) return std::nullopt;

  // Two co-located objects: at each of the n steps with a detection on the landmark (one per step, §4) the other
  // object was in view and missed.
  const double logMisses = static_cast<double>(detections.size()) * std::log1p(-detectionProbability);
  const std::vector<bool> every(detections.size(), true);
  const double logTogether = groupLabels(detections, every, true).logEvidence;  // ln P(s_A∪B)
  std::optional<LandmarkSplitDecision> best;
  for (Eigen::Index a = 0; a < classes; ++a) {
    for (Eigen::Index b = 0; b < classes; ++b) {
      if (a == b) continue;
      std::vector<bool> second(detections.size());
      std::size_t moved = 0;
      for (std::size_t i = 0; i < detections.size(); ++i) {
        second[i] = detections[i].classLikelihoods(b) > detections[i].classLikelihoods(a);
        moved += second[i] ? 1 : 0;
      }
      if (moved == 0 || moved == detections.size()) continue;
      const GroupLabels labelsFirst = groupLabels(detections, second, false);
      const GroupLabels labelsSecond = groupLabels(detections, second, true);
      const double logFirst = labelsFirst.logEvidence, logSecond = labelsSecond.logEvidence;
      if (!std::isfinite(logFirst) || !std::isfinite(logSecond)) continue;  // a group no single class explains
      const std::optional<GroupFit> first = fitGroup(detections, second, false);
      const std::optional<GroupFit> other = fitGroup(detections, second, true);
      if (!first || !other) continue;  // a group whose position its detections do not fix
      // At δ_A = δ_B: the geometry most favourable to one object (see the header).
      const std::optional<double> logGeometry =
          logGaussianAtZeroMean(Vector::Zero(d), first->covariance + other->covariance);
      if (!logGeometry) continue;
      const double score = *logGeometry + logTogether - logFirst - logSecond - logCartesianDensity - logMisses;
      if (!(score < 0.0) || (best && score >= best->score)) continue;
      if (second.front()) {  // the landmark keeps the object of its first detection; the other one moves
        second.flip();
        best = LandmarkSplitDecision{std::move(second), labelsSecond.mostProbableClass, labelsFirst.mostProbableClass,
                                     score, first->delta};
      } else {
        best = LandmarkSplitDecision{std::move(second), labelsFirst.mostProbableClass, labelsSecond.mostProbableClass,
                                     score, other->delta};
      }
    }
  }
  return best;
}

}  // namespace semslam
