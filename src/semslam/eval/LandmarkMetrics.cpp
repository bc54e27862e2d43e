#include "semslam/eval/LandmarkMetrics.h"

#include <cmath>
#include <map>
#include <string>
#include <type_traits>
#include <variant>

#include "semslam/core/InputError.h"

namespace semslam {

Vector landmarkPosition(const LandmarkState& state) {
  return std::visit(
      [](const auto& s) -> Vector {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SE2> || std::is_same_v<T, SE3>) {
          return s.translation();
        } else {
          return s;
        }
      },
      state);
}

Vector applyAlignment(const SimilarityTransform& alignment, const Vector& point) {
  if (point.size() == 3) return alignment.apply(point);
  if (point.size() == 2) {
    const Vector3 p = alignment.apply(Vector3(point.x(), point.y(), 0.0));
    return p.head<2>();
  }
  throw InputError("alignment: a point must have 2 or 3 coordinates, got " + std::to_string(point.size()));
}

int mostProbableClass(const Vector& probabilities) {
  if (probabilities.size() == 0) return -1;
  Eigen::Index best = 0;
  for (Eigen::Index c = 1; c < probabilities.size(); ++c) {
    if (probabilities(c) > probabilities(best)) best = c;
  }
  return static_cast<int>(best);
}

LandmarkMetrics evaluateLandmarks(const std::vector<EstimatedLandmark>& estimate,
                                  const std::vector<LandmarkTruth>& truth, const LandmarkMatching& matching,
                                  const SimilarityTransform& alignment) {
  std::map<int, const EstimatedLandmark*> estimated;
  for (const EstimatedLandmark& l : estimate) {
    if (!estimated.emplace(l.id, &l).second) {
      throw InputError("landmark metrics: estimated landmark id " + std::to_string(l.id) + " appears twice");
    }
  }
  std::map<int, const LandmarkTruth*> trueById;
  for (const LandmarkTruth& l : truth) {
    if (!trueById.emplace(l.id, &l).second) {
      throw InputError("landmark metrics: true landmark id " + std::to_string(l.id) + " appears twice");
    }
  }

  LandmarkMetrics metrics;
  metrics.estimated = estimate.size();
  metrics.truth = truth.size();
  metrics.countError = static_cast<long long>(estimate.size()) - static_cast<long long>(truth.size());

  double squares = 0.0;
  for (const LandmarkPair& pair : matching.pairs) {
    const auto e = estimated.find(pair.estimated);
    const auto t = trueById.find(pair.truth);
    if (e == estimated.end() || t == trueById.end()) continue;
    ++metrics.matched;
    const Vector p = applyAlignment(alignment, landmarkPosition(e->second->state));
    const Vector q = landmarkPosition(t->second->state);
    if (p.size() != q.size()) {
      throw InputError("landmark metrics: estimated landmark " + std::to_string(pair.estimated) + " is " +
                       std::to_string(p.size()) + "D but true landmark " + std::to_string(pair.truth) + " is " +
                       std::to_string(q.size()) + "D");
    }
    const double error = (p - q).norm();
    metrics.positionErrors.push_back(error);
    squares += error * error;

    const int trueClass = t->second->classIndex;
    const Vector& probabilities = e->second->classProbabilities;
    if (trueClass >= 0 && probabilities.size() > 0) {
      ++metrics.classesCompared;
      if (mostProbableClass(probabilities) == trueClass) ++metrics.classesCorrect;
    }
  }
  if (!metrics.positionErrors.empty()) {
    metrics.positionRmse = std::sqrt(squares / static_cast<double>(metrics.positionErrors.size()));
  }
  if (metrics.classesCompared > 0) {
    metrics.classAccuracy =
        static_cast<double>(metrics.classesCorrect) / static_cast<double>(metrics.classesCompared);
  }
  return metrics;
}

}  // namespace semslam
