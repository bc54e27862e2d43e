#include "semslam/models/UnicycleModel.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "semslam/models/OdometryWithFloor.h"

namespace semslam {

namespace {

void requireNonNegative(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string("UnicycleModel: ") + what + " must be finite and >= 0, got " +
                                std::to_string(value));
  }
}

}  // namespace

UnicycleModel::UnicycleModel(double velocityVariance, double angularVelocityVariance, const Vector3& floor)
    : velocityVariance_(velocityVariance), angularVelocityVariance_(angularVelocityVariance), floor_(floor) {
  requireNonNegative(velocityVariance, "the velocity variance");
  requireNonNegative(angularVelocityVariance, "the angular velocity variance");
  for (int i = 0; i < 3; ++i) requireNonNegative(floor(i), "every floor intensity");
}

SE2 UnicycleModel::increment(double v, double omega, double dt, Matrix32* Hinput) {
  if (!std::isfinite(v) || !std::isfinite(omega)) {
    throw std::invalid_argument("UnicycleModel: v and omega must be finite");
  }
  requireNonNegative(dt, "dt");
  const Vector3 xi(v * dt, 0.0, omega * dt);
  Matrix3 Jr;
  const SE2 delta = SE2::Exp(xi, Hinput ? &Jr : nullptr);
  if (Hinput) {
    // ∂ξ/∂(v, ω) = [dt 0; 0 0; 0 dt].
    Hinput->col(0) = Jr.col(0) * dt;
    Hinput->col(1) = Jr.col(2) * dt;
  }
  return delta;
}

Odometry UnicycleModel::integrate(double v, double omega, double dt) const {
  Matrix32 G;
  const SE2 delta = increment(v, omega, dt, &G);
  const Vector2 inputVariances(velocityVariance_, angularVelocityVariance_);
  const Matrix3 covariance = G * inputVariances.asDiagonal() * G.transpose();
  return odometryWithFloor<3>(delta, covariance, dt, floor_);
}

}  // namespace semslam
