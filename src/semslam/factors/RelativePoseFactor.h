#pragma once
// RelativePoseFactor<Pose>: the pose of a landmark (an object with an orientation) measured in the robot's
// frame, z ≈ x⁻¹ · o (paper B, footnote 1: landmarks observed with a full relative pose, SE2 or SE3).
//
// It is exactly a BetweenFactor from the robot pose to the landmark pose, with its error convention
// e = Log(z⁻¹ · (x⁻¹ · o)) and exact Jacobians; the name says what the measurement is.

#include "semslam/factors/BetweenFactor.h"

namespace semslam {

template <class Pose>
using RelativePoseFactor = BetweenFactor<Pose>;

}  // namespace semslam
