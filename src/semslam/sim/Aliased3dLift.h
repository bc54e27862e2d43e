#pragma once
// Aliased3dLift: paper A's aliased scenario in 3D, made from a 2D track (Aliased2dSimulator.h) by lifting it into
// SE(3) with a level robot and level objects (roll = pitch = 0; yaw = the 2D heading).
//
// Level (objectHeights empty): the same world in 3D. Poses (x, y, θ) ↦ (x, y, 0, yaw θ); objects likewise at z = 0;
// a range-bearing detection (r, b) ↦ (r, b, 0), a relative-position one (x, y) ↦ (x, y, 0). Covariances embed the
// 2D ones in the 3D tangent (translation first: x, y ↦ ρ_x, ρ_y; θ ↦ φ_z); z, roll and pitch get σ = levelSigma in
// the pose prior, the odometry and the objects' prior (their means are 0 and hold: "z fixed"), and the detection's
// elevation (or z) σ = elevationSigma (rad) or levelSigma (m). The hybrid belief on this log equals the 2D one:
// the extra rows of every factor have zero error and, up to the tilt's share (levelSigma² times the squared
// distances), the same variance for every candidate. Measured on paper A's scenario under its 10 m start prior:
// levelSigma 1e-4 moves normalised weights by ~1e-4, 1e-6 by less than 1e-6 (tests/hybrid/testHybrid3d.cpp).
// The default is 1e-4: a measurement log refuses a covariance whose standard deviations span more than a factor
// 1e6 (docs/measurement-log.md), and paper A's start prior has σ = 10 m in x and y, so 1e-6 would make a log that
// `semslam simulate aliased2d --lift-3d` cannot write; 1e-4 keeps a factor 100 of margin.
//
// With heights (objectHeights[j] for the j-th landmark of the truth, m): the objects stand at those heights, the
// robot stays level at z = 0, and the geometry is simulated anew in 3D: for each detection of the 2D track (the
// same objects, the same order, the same class scores: the viewpoint angle about a level object's vertical axis
// is the 2D one) z = h(x_k, l_o) + v with h the range-bearing-elevation model (RangeBearingElevationSensor3) and
// v ~ N(0, diag(Σ_rb, elevationSigma²)), dropped when the object is outside the 3D field of view (VisibilityModel3:
// a cone about the sensor's x axis, so an object high above a 2D edge-of-view detection leaves the view). The
// map prior's height of object j is drawn around the truth with σ = heightSigma, and its z variance is
// heightSigma². Range-bearing logs only in this mode. All draws come from the (seed, track) stream Lift3d.
//
// Throws std::invalid_argument for a log that is not 2D, a sensor the mode does not support, a height count that
// differs from the truth's landmarks, or a non-positive sigma.

#include <cstdint>
#include <vector>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

struct Aliased3dLift {
  std::vector<double> objectHeights;  ///< empty: level
  double levelSigma = 1e-4;           ///< m (z) and rad (roll, pitch): the weights move by ~levelSigma² · 10⁴
  double heightSigma = 0.3;           ///< m: the map prior's height uncertainty (with heights)
  double elevationSigma = 0.02;       ///< rad
};

MeasurementLog liftAliasedLogTo3d(const MeasurementLog& planar, const Aliased3dLift& lift, std::uint64_t seed = 1,
                                  std::uint32_t track = 0);

}  // namespace semslam
