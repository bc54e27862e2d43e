#pragma once
// How far a landmark can have moved as the robot sees it: a bound from the variables alone, with which a detection
// factor bounds how far its error has moved without evaluating it (Factor::whitenedErrorBoundForSeenMove,
// MaxMixtureFactor::chooseAt).
//
// Math. For a robot pose x = (R, t) in the world and a landmark at world position l, the landmark seen from the
// robot is p = Rᵀ(l − t). Between two states (x₀, l₀) and (x, l),
//     p − p₀ = Rᵀ[(l − l₀) − (t − t₀)] + (R − R₀)ᵀ(l₀ − t₀),
// so that
//     ‖p − p₀‖ ≤ ε = ‖l − l₀‖ + ‖t − t₀‖ + ‖R − R₀‖₂ ‖l₀ − t₀‖,
// and for rotations of the plane or of space ‖R − R₀‖₂ = ‖R − R₀‖_F / √2: R − R₀ = R₀(Q − I) with Q = R₀ᵀR a
// rotation by some angle φ, and Q − I has the singular value 2|sin(φ/2)| twice (and 0 in space). No trigonometry.
// A sensor fixed on the robot sees s⁻¹ p (s its mounting), which moves by exactly as much.

#include <cmath>
#include <optional>

#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"
#include "semslam/graph/Values.h"

namespace semslam {

/// ε above for poses `from` and `to` (SE2 or SE3) and the landmark's world positions in each.
template <class Pose, class Point>
double seenPointMove(const Pose& from, const Point& pointFrom, const Pose& to, const Point& pointTo) {
  const double rotationChange = (to.rotation().matrix() - from.rotation().matrix()).norm() / std::sqrt(2.0);
  return (pointTo - pointFrom).norm() + (to.translation() - from.translation()).norm() +
         rotationChange * (pointFrom - from.translation()).norm();
}

/// The same for values of a graph: a robot pose (SE2, SE3) and a landmark of the same dimension (a point, or an
/// object with a pose, whose position is its translation); std::nullopt for any other pair.
std::optional<double> seenPointMove(const Value& poseFrom, const Value& landmarkFrom, const Value& poseTo,
                                    const Value& landmarkTo);

}  // namespace semslam
