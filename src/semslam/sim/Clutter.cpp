#include "semslam/sim/Clutter.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "semslam/models/Angle.h"
#include "semslam/models/Sampling.h"

namespace semslam {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The full angle of the field of view: 0 or ≥ 2π means all around.
double fullAngle(double fieldOfView) {
  if (!std::isfinite(fieldOfView) || fieldOfView < 0.0) {
    throw std::invalid_argument("clutter: the field of view must be finite and >= 0, found " +
                                std::to_string(fieldOfView));
  }
  return fieldOfView == 0.0 || fieldOfView >= kTwoPi ? kTwoPi : fieldOfView;
}

void checkRange(double maxRange) {
  if (!std::isfinite(maxRange) || !(maxRange > 0.0)) {
    throw std::invalid_argument("clutter needs a sensor with a positive maximum range, found " +
                                std::to_string(maxRange));
  }
}

}  // namespace

int samplePoisson(double mean, std::mt19937& rng) {
  if (!std::isfinite(mean) || mean < 0.0 || mean > kMaxClutterMean) {
    throw std::invalid_argument("a Poisson mean must be in [0, " + std::to_string(kMaxClutterMean) + "], found " +
                                std::to_string(mean));
  }
  const double u = uniform01(rng);
  if (mean == 0.0) return 0;
  double probability = std::exp(-mean);
  double cumulative = probability;
  int k = 0;
  // The cap only matters when rounding leaves F just below a u close to 1.
  const int cap = static_cast<int>(mean + 40.0 * std::sqrt(mean) + 40.0);
  while (u >= cumulative && k < cap) {
    ++k;
    probability *= mean / k;
    cumulative += probability;
  }
  return k;
}

Vector2 uniformRangeBearing(double fieldOfView, double maxRange, std::mt19937& rng) {
  const double fov = fullAngle(fieldOfView);
  checkRange(maxRange);
  const double u1 = uniform01(rng);
  const double u2 = uniform01(rng);
  return Vector2(maxRange * std::sqrt(1.0 - u1), wrapAngle(fov * (u2 - 0.5)));
}

Vector3 uniformRangeBearingElevation(double fieldOfView, double maxRange, std::mt19937& rng) {
  const double halfAngle = 0.5 * fullAngle(fieldOfView);
  checkRange(maxRange);
  const double u1 = uniform01(rng);
  const double u2 = uniform01(rng);
  const double u3 = uniform01(rng);
  const double range = maxRange * std::cbrt(1.0 - u1);
  const double c = 1.0 - u2 * (1.0 - std::cos(halfAngle));
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  const double phi = kTwoPi * u3;
  const Vector3 d(c, s * std::cos(phi), s * std::sin(phi));
  return Vector3(range, std::atan2(d.y(), d.x()), std::atan2(d.z(), std::hypot(d.x(), d.y())));
}

}  // namespace semslam
