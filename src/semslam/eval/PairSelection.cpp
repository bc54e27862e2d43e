#include "semslam/eval/PairSelection.h"

#include <cmath>
#include <sstream>

#include "semslam/core/InputError.h"

namespace semslam {

namespace {

std::vector<PosePair> pairsByIndex(std::size_t n, std::size_t delta, bool allPairs) {
  std::vector<PosePair> pairs;
  if (allPairs) {
    for (std::size_t i = 0; i + delta < n; ++i) pairs.emplace_back(i, i + delta);
  } else {
    for (std::size_t i = 0; i + delta < n; i += delta) pairs.emplace_back(i, i + delta);
  }
  return pairs;
}

std::vector<PosePair> pairsByPath(const Trajectory& t, double delta, double tolerance, bool allPairs) {
  std::vector<PosePair> pairs;
  const std::size_t n = t.size();
  if (allPairs) {
    std::vector<double> accumulated(n, 0.0);  // np.cumsum: sequential
    for (std::size_t k = 1; k < n; ++k) accumulated[k] = accumulated[k - 1] + (t.position(k - 1) - t.position(k)).norm();
    for (std::size_t i = 0; i + 1 < n; ++i) {
      // evo: argmin over j > i of |(d_j - d_i) - delta| (first on ties). d_j - d_i does not decrease with j, so
      // the residual falls then rises: look next to the first j whose path reaches delta, then walk left over ties.
      const auto residual = [&](std::size_t j) { return std::abs((accumulated[j] - accumulated[i]) - delta); };
      std::size_t lo = i + 1, hi = n;  // first j in [i+1, n) with d_j - d_i >= delta, or n
      while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (accumulated[mid] - accumulated[i] >= delta) hi = mid; else lo = mid + 1;
      }
      std::size_t best = lo == n ? n - 1 : lo;
      if (lo > i + 1 && residual(lo - 1) <= residual(best)) best = lo - 1;
      while (best > i + 1 && residual(best - 1) == residual(best)) --best;
      if (residual(best) <= tolerance) pairs.emplace_back(i, best);
    }
    return pairs;
  }
  std::vector<std::size_t> ids;
  double path = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) path += (t.position(i) - t.position(i - 1)).norm();
    if (path >= delta) {
      ids.push_back(i);
      path = 0.0;
    }
  }
  for (std::size_t k = 1; k < ids.size(); ++k) pairs.emplace_back(ids[k - 1], ids[k]);
  return pairs;
}

std::string describe(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

}  // namespace

DeltaUnit parseDeltaUnit(const std::string& name) {
  if (name == "frames" || name == "f") return DeltaUnit::Frames;
  if (name == "m" || name == "meters" || name == "metres") return DeltaUnit::Meters;
  throw InputError("unknown delta unit '" + name + "' (expected frames or m)");
}

std::string toString(DeltaUnit unit) { return unit == DeltaUnit::Frames ? "frames" : "m"; }

std::vector<PosePair> selectPosePairs(const Trajectory& trajectory, double delta, DeltaUnit unit, bool allPairs,
                                      double relativeTolerance) {
  if (!std::isfinite(delta) || delta <= 0.0) throw InputError("RPE: delta must be a positive number, got " + describe(delta));
  if (!std::isfinite(relativeTolerance) || relativeTolerance < 0.0) {
    throw InputError("RPE: the relative delta tolerance must be >= 0, got " + describe(relativeTolerance));
  }
  std::vector<PosePair> pairs;
  if (unit == DeltaUnit::Frames) {
    if (delta != std::floor(delta)) throw InputError("RPE: delta in frames must be a whole number, got " + describe(delta));
    // A delta of at least the pose count pairs nothing (and a huge one would not fit a size_t).
    if (delta < static_cast<double>(trajectory.size())) {
      pairs = pairsByIndex(trajectory.size(), static_cast<std::size_t>(delta), allPairs);
    }
  } else {
    pairs = pairsByPath(trajectory, delta, delta * relativeTolerance, allPairs);
  }
  if (pairs.empty()) {
    throw InputError("RPE: delta = " + describe(delta) + " (" + toString(unit) +
                     ") produced no pose pair - try a smaller delta (the trajectory has " +
                     std::to_string(trajectory.size()) + " poses, " + describe(trajectory.pathLength()) + " m)");
  }
  return pairs;
}

}  // namespace semslam
