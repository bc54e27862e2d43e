#include "semslam/io/convert/Keyframing.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "semslam/models/OdometryComposition.h"

namespace semslam {

namespace {

double slotOf(double time, double start, double period) { return std::floor((time - start) / period + 1e-9); }

}  // namespace

std::vector<TimeStep> selectKeyframes(const std::vector<TimeStep>& steps, double period, KeyframeSummary* summary) {
  if (!std::isfinite(period) || period <= 0.0) {
    throw std::invalid_argument("selectKeyframes: the period must be finite and > 0");
  }
  KeyframeSummary counts;
  std::vector<TimeStep> kept;
  const double start = steps.empty() ? 0.0 : steps.front().time;
  std::size_t begin = 0;
  std::size_t lastKept = 0;  // index into `steps` of the previous keyframe
  while (begin < steps.size()) {
    // The slot [begin, end) and its keyframe.
    const double slot = slotOf(steps[begin].time, start, period);
    std::size_t end = begin + 1;
    while (end < steps.size() && slotOf(steps[end].time, start, period) == slot) ++end;
    std::size_t chosen = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (!steps[i].detections.empty()) {
        chosen = i;
        break;
      }
    }
    TimeStep keyframe;
    keyframe.time = steps[chosen].time;
    keyframe.detections = steps[chosen].detections;
    keyframe.truePose = steps[chosen].truePose;
    if (!kept.empty()) {
      for (std::size_t i = lastKept + 1; i <= chosen; ++i) {
        if (!steps[i].odometry) {
          throw std::invalid_argument("selectKeyframes: step " + std::to_string(i) + " has no odometry");
        }
      }
      Odometry composed = *steps[lastKept + 1].odometry;
      for (std::size_t i = lastKept + 2; i <= chosen; ++i) composed = composeOdometry(composed, *steps[i].odometry);
      keyframe.odometry.emplace(std::move(composed));
    }
    for (std::size_t i = begin; i < end; ++i) {
      if (i == chosen) continue;
      ++counts.droppedSteps;
      counts.droppedDetections += steps[i].detections.size();
    }
    kept.push_back(std::move(keyframe));
    counts.chosen.push_back(chosen);
    lastKept = chosen;
    begin = end;
  }
  counts.keptSteps = kept.size();
  if (summary != nullptr) *summary = std::move(counts);
  return kept;
}

std::size_t keepFirstSteps(std::vector<TimeStep>& steps, std::size_t maxSteps) {
  if (maxSteps == 0 || maxSteps >= steps.size()) return 0;
  std::size_t dropped = 0;
  for (std::size_t i = maxSteps; i < steps.size(); ++i) dropped += steps[i].detections.size();
  steps.resize(maxSteps);
  return dropped;
}

}  // namespace semslam
