#include "semslam/association/LandmarkLifecycle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace semslam {

LandmarkLifecycle::LandmarkLifecycle(Rule rule) : rule_(rule) {
  if (rule_.confirmations < 1) throw std::invalid_argument("provisional landmarks: confirmations must be >= 1");
  if (rule_.patience < 1) throw std::invalid_argument("provisional landmarks: patience must be >= 1");
  if (!(rule_.spacingSeconds >= 0.0) || !std::isfinite(rule_.spacingSeconds)) {
    throw std::invalid_argument("provisional landmarks: spacing must be finite and >= 0");
  }
  for (double viewpoint : {rule_.viewpointDistance, rule_.viewpointSigmas}) {
    if (!(viewpoint >= 0.0) || !std::isfinite(viewpoint)) {
      throw std::invalid_argument("provisional landmarks: viewpoint distance must be finite and >= 0");
    }
  }
}

int LandmarkLifecycle::addConfirmed() {
  landmarks_.push_back({});
  return size() - 1;
}

int LandmarkLifecycle::addProvisional(double birthTime, const Vector& birthRobotPosition) {
  Entry entry;
  entry.state = State::Provisional;
  entry.counted = 1;  // the birth detection
  entry.lastCountedTime = birthTime;
  entry.lastCountedPosition = birthRobotPosition;
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

bool LandmarkLifecycle::observe(int landmark, double time, const Vector& robotPosition, double positionSigma) {
  if (!provisional(landmark)) return false;
  Entry& entry = provisionalEntry(landmark);
  // Strictly less than Δt is too soon; the tolerance absorbs timestamps that are multiples of a period in floats.
  if (time - entry.lastCountedTime < rule_.spacingSeconds * (1.0 - 1e-9)) return false;
  const double viewpoint = std::max(rule_.viewpointDistance, rule_.viewpointSigmas * positionSigma);  // D
  if (viewpoint > 0.0 && robotPosition.size() == entry.lastCountedPosition.size() &&
      (robotPosition - entry.lastCountedPosition).norm() < viewpoint) {
    return false;
  }
  entry.lastCountedTime = time;
  entry.lastCountedPosition = robotPosition;
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
