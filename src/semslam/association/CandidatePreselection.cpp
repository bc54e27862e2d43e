#include "semslam/association/CandidatePreselection.h"

#include <algorithm>
#include <stdexcept>

#include "semslam/association/ClassBelief.h"
#include "semslam/association/PreselectionRadius.h"

namespace semslam {
namespace {

/// The grid's cell size before any query: the sensor's range scale.
constexpr double kDefaultCellSize = 5.0;
/// The grid is re-binned when the typical query radius leaves [h / f, f h].
constexpr double kCellSizeTolerance = 4.0;

LogHeader withoutMap(const LogHeader& header) {
  LogHeader copy = header;
  copy.landmarkPriors.clear();
  copy.landmarkTruth.clear();
  return copy;
}

/// The position part of a landmark value, without allocating (the walk over the estimate runs every step).
Vector3 paddedPosition(const Value& value) {
  return std::visit(
      [](const auto& v) -> Vector3 {
        using V = std::decay_t<decltype(v)>;
        Vector3 p = Vector3::Zero();
        if constexpr (std::is_same_v<V, Point2>) p.head<2>() = v;
        else if constexpr (std::is_same_v<V, Point3>) p = v;
        else if constexpr (std::is_same_v<V, SE2>) p.head<2>() = v.translation();
        else if constexpr (std::is_same_v<V, SE3>) p = v.translation();
        else throw std::invalid_argument("a rotation is not a landmark");
        return p;
      },
      value);
}

}  // namespace

CandidatePreselection::CandidatePreselection(const LogHeader& header, const AssociationGate& gate)
    : header_(withoutMap(header)),
      factory_(header_),
      gate_(gate),
      grid_(header.dimension, header.sensor.maxRange > 0.0 ? header.sensor.maxRange / 2.0 : kDefaultCellSize) {}

void CandidatePreselection::trackNew(const Smoother& smoother, int landmarkCount,
                                     const std::function<Key(int)>& keyOf, const std::function<bool(int)>& active) {
  const int d = grid_.dimension();
  for (int j = grid_.size(); j < landmarkCount; ++j) {
    const Key key = keyOf(j);
    if (!keys_.empty() && key <= keys_.back()) keysAscending_ = false;
    keys_.push_back(key);
    const double spread = active(j) ? kSpreadSafety * positionSpread(smoother.marginalCovariance(key), d) : 0.0;
    grid_.set(j, paddedPosition(smoother.estimate().value(key)).head(d), spread);
    spreadSum_ += spread;
  }
}

void CandidatePreselection::synchronise(const Values& estimate) {
  const int d = grid_.dimension();
  const auto update = [&](int j, const Value& value) {
    const Vector3 position = paddedPosition(value);
    if (position != grid_.position(j)) grid_.set(j, position.head(d), grid_.spread(j));
  };
  if (!keysAscending_) {
    for (int j = 0; j < grid_.size(); ++j) update(j, estimate.value(keys_[static_cast<std::size_t>(j)]));
    return;
  }
  // Both sequences ascend: one merge walk, no lookups.
  auto it = estimate.begin();
  for (int j = 0; j < grid_.size(); ++j) {
    const Key key = keys_[static_cast<std::size_t>(j)];
    while (it != estimate.end() && it->first < key) ++it;
    if (it == estimate.end() || it->first != key) throw std::logic_error("a tracked landmark left the estimate");
    update(j, it->second);
  }
}

void CandidatePreselection::adaptCellSize(double typicalRadius) {
  if (!(typicalRadius > 0.0) || !std::isfinite(typicalRadius)) return;
  const double h = grid_.cellSize();
  if (typicalRadius > h * kCellSizeTolerance || typicalRadius < h / kCellSizeTolerance) grid_.rebuild(typicalRadius);
}

std::vector<int> CandidatePreselection::select(const Smoother& smoother, Key pose,
                                               const std::vector<Detection>& detections, bool jointGate,
                                               int landmarkCount, const std::function<Key(int)>& keyOf,
                                               const std::function<bool(int)>& active) {
  if (landmarkCount < grid_.size()) throw std::invalid_argument("landmarks are never removed");
  trackNew(smoother, landmarkCount, keyOf, active);
  synchronise(smoother.estimate());
  if (landmarkCount == 0 || detections.empty()) return {};
  const auto everyActiveLandmark = [&] {
    std::vector<int> every;
    for (int j = 0; j < landmarkCount; ++j) {
      if (active(j)) every.push_back(j);
    }
    return every;
  };

  const Value& poseValue = smoother.estimate().value(pose);
  const Matrix poseCovariance = smoother.marginalCovariance(pose);
  const int m = gateDegreesOfFreedom(header_.sensor, header_.dimension);
  const double meanSpread = spreadSum_ / static_cast<double>(grid_.size());
  std::vector<int> selected;
  double radiusSum = 0.0;
  for (const Detection& detection : detections) {
    const double allowance = jointGate ? semanticGateAllowance(semanticLikelihoods(header_, detection)) : 0.0;
    const double threshold = gate_.threshold(m) + allowance;
    const std::optional<PreselectionBall> ball =
        preselectionBall(factory_, header_.sensor, poseValue, poseCovariance, detection, threshold);
    if (!ball) return everyActiveLandmark();  // §7: no finite ball holds every landmark that can pass
    for (int j : grid_.within(ball->center, ball->base, ball->slope)) {
      if (active(j)) selected.push_back(j);
    }
    radiusSum += ball->base + ball->slope * meanSpread;
  }
  std::sort(selected.begin(), selected.end());
  selected.erase(std::unique(selected.begin(), selected.end()), selected.end());
  adaptCellSize(radiusSum / static_cast<double>(detections.size()));
  return selected;
}

void CandidatePreselection::refresh(const JointMarginal& marginal, const std::vector<int>& landmarks) {
  const int d = grid_.dimension();
  for (int j : landmarks) {
    const double spread = kSpreadSafety * positionSpread(marginal.at(keys_.at(static_cast<std::size_t>(j))), d);
    spreadSum_ += spread - grid_.spread(j);
    grid_.set(j, grid_.position(j).head(d), spread);
  }
}

}  // namespace semslam
