#pragma once
// Angles: wrapping to the principal interval (−π, π].

#include <cmath>
#include <numbers>

namespace semslam {

/// The angle equal to `angle` modulo 2π in (−π, π].
inline double wrapAngle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * std::numbers::pi);  // in [−π, π]
  if (wrapped <= -std::numbers::pi) wrapped += 2.0 * std::numbers::pi;
  return wrapped;
}

}  // namespace semslam
