#pragma once
// MeasurementSampling: noisy geometric measurements of a true landmark, and the order in which a step's
// detections are listed. Shared by the simulators (aliased2d, semantic).
//
//   z = h(x, l) + v,   v ~ N(0, Σ)   (Sampling.h's sampleGaussian: 4·d engine outputs per draw, always consumed)
// with h the sensor model (RangeBearingSensor2: (range, bearing); RangeBearingElevationSensor3: (range, bearing,
// elevation)), the bearing wrapped to (−π, π]. Edge cases of additive noise on a polar measurement:
//   - a noisy range ≤ 0 has no meaning (the log requires a positive range): the detection is dropped (nullopt),
//     as a sensor reporting no return. With the default noise levels this needs a landmark within a few
//     standard deviations of the sensor, which the simulators' layouts avoid;
//   - a noisy elevation outside [−π/2, π/2] (a landmark almost straight above or below) is clamped to the
//     interval.
//
// Detection order: a step's detections are listed by increasing measured bearing (ties keep their order), the
// order a scanning sensor reports them in; it carries no information about which landmark produced which.

#include <optional>
#include <random>
#include <vector>

#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/models/RangeBearingElevationSensor3.h"
#include "semslam/models/RangeBearingSensor2.h"

namespace semslam {

/// A noisy (range, bearing) of `point` seen from `robot`; nullopt when the noisy range is not positive.
std::optional<Vector> sampleRangeBearing(const RangeBearingSensor2& sensor, const SE2& robot, const Point2& point,
                                         const Matrix& covariance, std::mt19937& rng);

/// A noisy (range, bearing, elevation); nullopt when the noisy range is not positive.
std::optional<Vector> sampleRangeBearingElevation(const RangeBearingElevationSensor3& sensor, const SE3& robot,
                                                  const Point3& point, const Matrix& covariance, std::mt19937& rng);

/// Sorts detections by increasing geometry(1) (the bearing), stably.
void sortDetectionsByBearing(std::vector<Detection>& detections);

}  // namespace semslam
