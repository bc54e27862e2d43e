#include "semslam/eval/Association.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "semslam/core/InputError.h"

namespace semslam {

namespace {

/// numpy's argmin of |shifted[j] - t| over all j: the first index of the smallest difference.
std::size_t nearestLinear(const std::vector<double>& shifted, double t) {
  std::size_t best = 0;
  double bestDiff = std::abs(shifted[0] - t);
  for (std::size_t j = 1; j < shifted.size(); ++j) {
    const double d = std::abs(shifted[j] - t);
    if (d < bestDiff) {
      bestDiff = d;
      best = j;
    }
  }
  return best;
}

/// The same for sorted `shifted`: |shifted[j] - t| falls and then rises with j (rounding is monotone), so the
/// smallest is next to the first stamp >= t; walk left over equal differences to return the first index.
std::size_t nearestSorted(const std::vector<double>& shifted, double t) {
  const auto k = static_cast<std::size_t>(std::lower_bound(shifted.begin(), shifted.end(), t) - shifted.begin());
  std::size_t best;
  if (k == 0) {
    best = 0;
  } else if (k == shifted.size()) {
    best = k - 1;
  } else {
    best = std::abs(shifted[k - 1] - t) <= std::abs(shifted[k] - t) ? k - 1 : k;
  }
  const double bestDiff = std::abs(shifted[best] - t);
  while (best > 0 && std::abs(shifted[best - 1] - t) == bestDiff) --best;
  return best;
}

std::string describe(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

}  // namespace

TimeMatches matchingTimeIndices(const std::vector<double>& stamps1, const std::vector<double>& stamps2,
                                double maxDiff, double offset2) {
  TimeMatches matches;
  if (stamps2.empty()) return matches;
  std::vector<double> shifted(stamps2);
  for (double& s : shifted) s += offset2;
  const bool sorted = std::is_sorted(shifted.begin(), shifted.end());
  for (std::size_t i = 0; i < stamps1.size(); ++i) {
    const std::size_t j = sorted ? nearestSorted(shifted, stamps1[i]) : nearestLinear(shifted, stamps1[i]);
    if (std::abs(shifted[j] - stamps1[i]) <= maxDiff) {
      matches.first.push_back(i);
      matches.second.push_back(j);
    }
  }
  return matches;
}

AssociatedTrajectories associateTrajectories(const Trajectory& reference, const Trajectory& estimate,
                                             double maxDiff, double offset) {
  if (!std::isfinite(maxDiff) || maxDiff < 0.0) {
    throw InputError("association: max time difference must be a finite number >= 0, got " + describe(maxDiff));
  }
  if (!std::isfinite(offset)) throw InputError("association: time offset must be finite");
  if (reference.empty() || estimate.empty()) throw InputError("association: a trajectory has no poses");

  AssociatedTrajectories result;
  if (!reference.hasTimestamps() || !estimate.hasTimestamps()) {
    if (reference.size() != estimate.size()) {
      throw InputError("association: a trajectory without timestamps (KITTI) is paired by index and needs as many "
                       "poses as the other one: reference has " + std::to_string(reference.size()) +
                       ", estimate has " + std::to_string(estimate.size()));
    }
    for (std::size_t i = 0; i < reference.size(); ++i) result.referenceIndices.push_back(i);
    result.estimateIndices = result.referenceIndices;
    result.reference = reference;
    result.estimate = estimate;
    return result;
  }

  // evo: start from the trajectory with fewer poses; on a tie that is the second one (the estimate).
  const bool estimateLonger = estimate.size() > reference.size();
  if (estimateLonger) {
    const TimeMatches m = matchingTimeIndices(reference.timestamps(), estimate.timestamps(), maxDiff, offset);
    result.referenceIndices = m.first;
    result.estimateIndices = m.second;
  } else {
    const TimeMatches m = matchingTimeIndices(estimate.timestamps(), reference.timestamps(), maxDiff, -offset);
    result.estimateIndices = m.first;
    result.referenceIndices = m.second;
  }
  if (result.referenceIndices.empty()) {
    throw InputError("association: found no matching timestamps between reference and estimate with max. time "
                     "difference " + describe(maxDiff) + " s and time offset " + describe(offset) + " s");
  }
  result.reference = reference.subset(result.referenceIndices);
  result.estimate = estimate.subset(result.estimateIndices);
  return result;
}

}  // namespace semslam
