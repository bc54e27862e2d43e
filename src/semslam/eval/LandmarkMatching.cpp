#include "semslam/eval/LandmarkMatching.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "semslam/solve/HungarianAssignment.h"
#include "semslam/core/InputError.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

std::optional<int> LandmarkMatching::truthOf(int estimated) const {
  const auto it = std::lower_bound(pairs.begin(), pairs.end(), estimated,
                                   [](const LandmarkPair& p, int id) { return p.estimated < id; });
  if (it == pairs.end() || it->estimated != estimated) return std::nullopt;
  return it->truth;
}

std::optional<int> LandmarkMatching::estimateOf(int truth) const {
  for (const LandmarkPair& p : pairs) {
    if (p.truth == truth) return p.estimated;
  }
  return std::nullopt;
}

std::size_t LandmarkMatching::sharedDetections() const {
  std::size_t total = 0;
  for (const LandmarkPair& p : pairs) total += p.sharedDetections;
  return total;
}

LandmarkMatching matchLandmarks(const std::vector<DetectionAssociation>& detections) {
  std::map<int, int> rowOf, columnOf;  // id -> index, in ascending id order once numbered
  std::map<std::pair<int, int>, std::size_t> shared;
  for (const DetectionAssociation& d : detections) {
    if (d.truth < kUnknownTruth) {
      throw InputError("landmark matching: invalid true landmark id " + std::to_string(d.truth) +
                       " (ids are >= 0, -1 for clutter, or -2 for unknown)");
    }
    if (d.truth == kUnknownTruth) continue;  // not scored: as if the detection had no truth
    if (d.estimate) rowOf.emplace(*d.estimate, 0);
    if (d.truth != kNotALandmark) columnOf.emplace(d.truth, 0);
    if (d.estimate && d.truth != kNotALandmark) ++shared[{*d.estimate, d.truth}];
  }
  std::vector<int> estimatedIds, trueIds;
  for (auto& [id, index] : rowOf) {
    index = static_cast<int>(estimatedIds.size());
    estimatedIds.push_back(id);
  }
  for (auto& [id, index] : columnOf) {
    index = static_cast<int>(trueIds.size());
    trueIds.push_back(id);
  }

  Matrix weights = Matrix::Zero(static_cast<Eigen::Index>(estimatedIds.size()),
                                static_cast<Eigen::Index>(trueIds.size()));
  for (const auto& [key, count] : shared) weights(rowOf[key.first], columnOf[key.second]) = static_cast<double>(count);

  const Assignment assignment = maximumWeightAssignment(weights);
  LandmarkMatching matching;
  for (std::size_t row = 0; row < estimatedIds.size(); ++row) {
    const int column = assignment.rowToColumn[row];
    if (column < 0) continue;
    const double count = weights(static_cast<Eigen::Index>(row), column);
    if (count <= 0.0) continue;
    matching.pairs.push_back({estimatedIds[row], trueIds[static_cast<std::size_t>(column)],
                              static_cast<std::size_t>(count)});
  }
  return matching;
}

}  // namespace semslam
