#pragma once
// Keyframing: one time step per period, with the odometry in between composed (paper B sampled its detection
// keyframes at 1 Hz), and truncation to the first N steps.
//
// Which steps are kept
//   Time is cut into slots [t₀ + k·T, t₀ + (k+1)·T), t₀ the first step's time and T the period (a step at
//   t₀ + k·T to within 1e-9·T belongs to slot k). Each slot that holds a step keeps exactly one: its first step
//   that has detections, or its first step when none has. So a 10 Hz log keyframed at 1 s keeps one step per
//   second, and a keyframe falls on a step with detections whenever its second has one (MRCLAM's detections come
//   between its odometry stamps, so "the first step of each slot" would keep almost none of them).
// What the kept steps carry
//   Their own detections and true pose. Their odometry is the composition (composeOdometry, first order in the
//   covariance) of the increments of every step after the previous kept step up to and including this one; the
//   first kept step has none. The detections of the dropped steps are dropped and counted.
//
// Both functions keep the steps' order and throw std::invalid_argument for a period that is not finite and > 0, or
// a step other than the first without odometry.

#include <cstddef>
#include <vector>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

struct KeyframeSummary {
  std::size_t keptSteps = 0;
  std::size_t droppedSteps = 0;
  std::size_t droppedDetections = 0;
  std::vector<std::size_t> chosen;  ///< per kept step, its index in the input steps
};

/// The keyframes of `steps` at `period` seconds, as described above.
std::vector<TimeStep> selectKeyframes(const std::vector<TimeStep>& steps, double period,
                                      KeyframeSummary* summary = nullptr);

/// Keeps the first `maxSteps` steps (all when maxSteps is 0 or at least steps.size()). Returns the number of
/// detections dropped with the removed steps.
std::size_t keepFirstSteps(std::vector<TimeStep>& steps, std::size_t maxSteps);

}  // namespace semslam
