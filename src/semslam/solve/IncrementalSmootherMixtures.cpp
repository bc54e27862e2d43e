// IncrementalSmoother, the mixtures' component re-choice (IncrementalSmoother.h, class comment "Mixtures", steps
// 0–2; docs/incremental-smoother.md "Mixtures"; docs/association-front-end.md §6).

#include "semslam/solve/IncrementalSmoother.h"

#include <algorithm>
#include <cmath>

namespace semslam {

std::vector<int> IncrementalSmoother::switchedMixtures(const std::vector<int>& slots, bool atTheta) {
  std::vector<int>& seen = scratch_.slotStamp;
  seen.resize(slots_.size(), 0);
  const int stamp = ++scratch_.stamp;
  const Values& estimate = this->estimate();
  std::vector<int> switched;
  for (int slot : slots) {
    const Slot& s = slots_[slot];
    if (!s.factor || seen[slot] == stamp) continue;  // removed since, or listed twice
    seen[slot] = stamp;
    if (!atTheta && !s.linearization) continue;  // stale: it chooses afresh when linearized
    ++lastUpdate_.checkedMixtures;
    const int chosen = atTheta ? s.factor->activeComponent(theta_) : s.component;
    if (chosen >= 0 && s.factor->activeComponent(estimate) != chosen) switched.push_back(slot);
  }
  return switched;
}

void IncrementalSmoother::relinearizeMixtures(const std::vector<int>& mixtures, MarkedVariables& marked) {
  for (int slot : mixtures) {
    ++lastUpdate_.componentSwitches;
    // A variable with Δ = 0 is at the estimate already; relinearizing any other one re-linearizes the mixture.
    for (int v : slots_[slot].variables) {
      if (deltaNorm(v) > 0.0) relinearizeAndMark(v, marked);
    }
  }
}

std::vector<int> IncrementalSmoother::touchedMixtures(double threshold) {
  std::vector<int> touched = scratch_.linearizedMixtures;
  touched.insert(touched.end(), unsettledMixtures_.begin(), unsettledMixtures_.end());
  unsettledMixtures_.clear();
  for (int v : scratch_.changedVariables) {
    if (!movedSinceMixtureCheck(v, threshold)) continue;
    for (int slot : variables_[v].factors) {
      if (slots_[slot].component >= 0) touched.push_back(slot);
    }
  }
  scratch_.linearizedMixtures.clear();
  scratch_.changedVariables.clear();
  return touched;
}

bool IncrementalSmoother::movedSinceMixtureCheck(int variable, double threshold) {
  const Variable& v = variables_[variable];
  double moved = 0.0;
  for (int i = 0; i < v.dimension; ++i) {
    moved = std::max(moved, std::abs(delta_[v.offset + i] - deltaAtMixtureCheck_[v.offset + i]));
  }
  if (moved <= threshold) return false;
  std::copy_n(delta_.begin() + v.offset, v.dimension, deltaAtMixtureCheck_.begin() + v.offset);
  return true;
}

void IncrementalSmoother::settleMixtures(const std::vector<bool>& constrainedLast, double wildfireThreshold) {
  for (int round = 0;; ++round) {
    std::vector<int> switched = switchedMixtures(touchedMixtures(wildfireThreshold), false);
    if (switched.empty()) return;
    if (round == params_.maxSwitchRounds) {
      unsettledMixtures_ = std::move(switched);  // checked first at the next update
      return;
    }
    MarkedVariables marked;
    marked.isMarked.assign(variables_.size(), 0);
    relinearizeMixtures(switched, marked);
    ++lastUpdate_.switchRounds;
    const std::vector<int> newCliques = reeliminate(marked.list, constrainedLast);
    backSubstitute(newCliques, wildfireThreshold);
  }
}

}  // namespace semslam
