#include "semslam/association/LandmarkLifecycle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace semslam {

LandmarkLifecycle::LandmarkLifecycle(Rule rule) : rule_(rule) {
  if (rule_.confirmations < 1) throw std::invalid_argument("provisional landmarks: confirmations must be >= 1");
  if (rule_.patience < 1) throw std::invalid_argument("provisional landmarks: patience must be >= 1");
  if (!(rule_.spacingPeriods >= 0.0) || !std::isfinite(rule_.spacingPeriods)) {
    throw std::invalid_argument("provisional landmarks: spacing must be finite and >= 0");
  }
}

void LandmarkLifecycle::observeStepTime(double time) {
  if (lastStepTime_) {
    const double period = time - *lastStepTime_;
    sortedPeriods_.insert(std::upper_bound(sortedPeriods_.begin(), sortedPeriods_.end(), period), period);
  }
  lastStepTime_ = time;
}

double LandmarkLifecycle::minimumSpacing() const {
  if (sortedPeriods_.empty()) return 0.0;
  const std::size_t n = sortedPeriods_.size();
  const double median = n % 2 == 1 ? sortedPeriods_[n / 2] : 0.5 * (sortedPeriods_[n / 2 - 1] + sortedPeriods_[n / 2]);
  return rule_.spacingPeriods * median;
}

int LandmarkLifecycle::addConfirmed() {
  landmarks_.push_back({});
  return size() - 1;
}

int LandmarkLifecycle::addProvisional(double birthTime, const Vector& birthSensorPosition) {
  Entry entry;
  entry.state = State::Provisional;
  entry.counted = 1;  // the birth detection
  entry.lastCountedTime = birthTime;
  entry.lastCountedPosition = birthSensorPosition;
  landmarks_.push_back(entry);
  if (rule_.confirmations <= 1) landmarks_.back().state = State::Confirmed;
  return size() - 1;
}

bool LandmarkLifecycle::active(int landmark) const {
  const State s = state(landmark);
  return s == State::Provisional || s == State::Confirmed;
}

std::optional<int> LandmarkLifecycle::mergedInto(int landmark) const {
  if (state(landmark) != State::Merged) return std::nullopt;
  int target = landmarks_[static_cast<std::size_t>(landmark)].mergedInto;
  while (state(target) == State::Merged) target = landmarks_[static_cast<std::size_t>(target)].mergedInto;
  return target;
}

LandmarkLifecycle::Entry& LandmarkLifecycle::provisionalEntry(int landmark) {
  Entry& entry = landmarks_.at(static_cast<std::size_t>(landmark));
  if (entry.state != State::Provisional) {
    throw std::logic_error("landmark " + std::to_string(landmark) + " is not provisional");
  }
  return entry;
}

bool LandmarkLifecycle::observe(int landmark, double time, const Vector& sensorPosition) {
  if (!provisional(landmark)) return false;
  Entry& entry = provisionalEntry(landmark);
  // Strictly less than Δt is too soon; the tolerance absorbs timestamps that are multiples of a period in floats.
  if (time - entry.lastCountedTime < minimumSpacing() * (1.0 - 1e-9)) return false;
  if (rule_.viewpointDistance > 0.0 && sensorPosition.size() == entry.lastCountedPosition.size() &&
      (sensorPosition - entry.lastCountedPosition).norm() < rule_.viewpointDistance) {
    return false;
  }
  entry.lastCountedTime = time;
  entry.lastCountedPosition = sensorPosition;
  if (++entry.counted < rule_.confirmations) return false;
  entry.state = State::Confirmed;
  return true;
}

bool LandmarkLifecycle::passedInField(int landmark) {
  Entry& entry = provisionalEntry(landmark);
  return ++entry.inFieldSteps >= rule_.patience;
}

void LandmarkLifecycle::drop(int landmark) { provisionalEntry(landmark).state = State::Dropped; }

void LandmarkLifecycle::merge(int landmark, int into) {
  if (landmark == into || !active(into) || !active(landmark)) {
    throw std::logic_error("merge of an inactive landmark, into an inactive landmark or into itself");
  }
  Entry& entry = landmarks_.at(static_cast<std::size_t>(landmark));
  entry.state = State::Merged;
  entry.mergedInto = into;
}

}  // namespace semslam
