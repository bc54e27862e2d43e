#pragma once
// The spread of a covariance: the standard deviation along its principal axis, √λmax(Σ), the radius of the
// one-sigma ellipsoid's longest axis. Used wherever a covariance must be bounded by a single length (the
// pre-selection ball of the association front end, a detection's position error).
//
// Invariants: Σ is symmetric positive semi-definite up to rounding (negative eigenvalues from rounding count as 0);
// an empty Σ has spread 0, a Σ with a non-finite entry spread +∞ (no bound).

#include "semslam/geometry/Matrix.h"

namespace semslam {

/// √λmax of a symmetric positive semi-definite matrix (see above).
double largestStandardDeviation(const Matrix& covariance);

}  // namespace semslam
