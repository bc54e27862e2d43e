#pragma once
// The magnitudes a measurement log (and an aliased2d scenario) may hold, so that no finite input makes the
// solvers overflow (issue 16: an odometry or detection of 1e308 is finite, yet every chi2, Jacobian and marginal
// through it became infinite or NaN far from the line that caused it). Refused at input with the file, the line
// and the field (docs/measurement-log.md, "Limits"):
//   - a coordinate (a position, a translation, a range, an angle, a sensor offset or range limit) beyond
//     kMaxCoordinate in magnitude;
//   - a range below kMinRange (a smaller one puts a landmark on its sensor in floating point, at kMaxCoordinate);
//   - a covariance whose diagonal (a variance) is outside [kMinVariance, kMaxVariance].
// Within these bounds a squared error weighted by an information is at most ~1e50, far from the largest double,
// and the products the solvers form stay finite. They do not promise a well-conditioned system: a log at the edge
// of them can still leave a variable numerically free, which the solver reports (solve/UnconstrainedSystem.h).
//
// Internal to the io layer, like JsonField.h.

namespace semslam::jsonio {

/// 10,000 km: beyond any place on Earth in an Earth-centred frame, metres or radians.
inline constexpr double kMaxCoordinate = 1e7;
/// A micrometre: at kMaxCoordinate a double still resolves 2e-9 m.
inline constexpr double kMinRange = 1e-6;
/// A standard deviation of 1e-9 (a nanometre, a nanoradian) ...
inline constexpr double kMinVariance = 1e-18;
/// ... to 1e9 (a million kilometres).
inline constexpr double kMaxVariance = 1e18;

}  // namespace semslam::jsonio
