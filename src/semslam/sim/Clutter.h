#pragma once
// Clutter: false detections, as the semantic simulator makes them (paper B's outliers: detections that no
// landmark produced).
//
// Per time step the number of false detections is Poisson with mean λ (`--clutter`), and each is a point
// uniformly distributed over the sensor's field of view up to its maximum range R:
//   2D (area-uniform over the sector |bearing| ≤ fov/2, 0 < r ≤ R):
//       r = R sqrt(1 − u₁),   bearing = fov (u₂ − ½)                  (fov: the full angle; all around: 2π)
//   3D (volume-uniform over the cone of half-angle a = fov/2 about the sensor's x axis, 0 < r ≤ R):
//       r = R (1 − u₁)^{1/3},   cos(angle off axis) c = 1 − u₂ (1 − cos a),   azimuth about the axis φ = 2π u₃,
//       direction d = (c, s cos φ, s sin φ), s = sqrt(1 − c²),
//       bearing = atan2(d_y, d_x),   elevation = atan2(d_z, ‖(d_x, d_y)‖).
// (u_i: uniform01 draws; 1 − u ∈ (0, 1] keeps r > 0.) These are exact measurements of the uniform point: adding
// sensor noise to a uniformly random point would change nothing but its distribution near the boundary.
//
// The Poisson count inverts the CDF on a single uniform01 draw: k is the least integer with u < F(k). The mean
// must be finite and in [0, 100] (std::invalid_argument otherwise); a field of view 0 or ≥ 2π means all around,
// and the maximum range must be positive (a uniform point needs a bounded region).

#include <random>

#include "semslam/geometry/Matrix.h"

namespace semslam {

inline constexpr double kMaxClutterMean = 100.0;

/// A Poisson(mean) count.
int samplePoisson(double mean, std::mt19937& rng);

/// (range, bearing) of a point uniform over the 2D field of view.
Vector2 uniformRangeBearing(double fieldOfView, double maxRange, std::mt19937& rng);

/// (range, bearing, elevation) of a point uniform over the 3D field of view (a circular cone).
Vector3 uniformRangeBearingElevation(double fieldOfView, double maxRange, std::mt19937& rng);

}  // namespace semslam
