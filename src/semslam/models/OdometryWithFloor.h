#pragma once
// The last step of the motion models (UnicycleModel, VelocityModel3): an integrated increment and the covariance
// propagated from its inputs, G Σ_u Gᵀ, become one Odometry with
//   Σ = G Σ_u Gᵀ + dt · diag(q),   stored as ½ (Σ + Σᵀ)
// where q is the model's floor (white-noise intensity per second on every tangent direction). The symmetrisation
// removes round-off asymmetry, so the stored covariance is exactly symmetric.

#include "semslam/geometry/Matrix.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

template <int N>
Odometry odometryWithFloor(const Pose& increment, MatrixN<N, N> propagatedCovariance, double dt,
                           const VectorN<N>& floor) {
  propagatedCovariance.diagonal() += dt * floor;
  Odometry result;
  result.increment = increment;
  result.covariance = 0.5 * (propagatedCovariance + propagatedCovariance.transpose());
  return result;
}

}  // namespace semslam
