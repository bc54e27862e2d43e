#pragma once
// The magnitudes a measurement log (and an aliased2d scenario) may hold, so that no finite input makes the
// solvers overflow (issue 16: an odometry or detection of 1e308 is finite, yet every chi2, Jacobian and marginal
// through it became infinite or NaN far from the line that caused it). Refused at input with the file, the line
// and the field (docs/measurement-log.md, "Limits"):
//   - a coordinate (a position, a translation, a range, an angle, a sensor offset or range limit) beyond
//     kMaxCoordinate in magnitude;
//   - a range below kMinRange (a smaller one puts a landmark on its sensor in floating point, at kMaxCoordinate);
//   - a covariance whose diagonal (a variance) is outside [kMinVariance, kMaxVariance];
//   - a covariance whose condition number (largest over smallest eigenvalue) exceeds kMaxConditionNumber.
// Within these bounds a squared error weighted by an information is at most ~1e50, far from the largest double,
// and the products the solvers form stay finite; and every covariance stays positive definite through the
// rotations, sums and inverses the models take of it (a covariance of diag(1e-18, 1e18) passed the reader's
// Cholesky test, then a rotated copy of it was "not positive definite" inside the hybrid belief, at no line).
// They do not promise a well-conditioned system: a log at the edge of them can still leave a variable numerically
// free, which the solver reports (solve/UnconstrainedSystem.h).
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
/// Standard deviations along a covariance's axes within a factor 1e6 of each other. A rotation of a covariance
/// errs by about 1e-16 times its largest eigenvalue, so the smallest stays positive with four digits to spare. The
/// real datasets' covariances reach 1.3e3 (Starry Night's stereo detections; docs/measurement-log.md, "Limits").
inline constexpr double kMaxConditionNumber = 1e12;

}  // namespace semslam::jsonio
