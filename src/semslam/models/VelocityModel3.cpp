#include "semslam/models/VelocityModel3.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>

#include "semslam/models/OdometryWithFloor.h"

namespace semslam {

namespace {

Matrix6 diagonalCovariance(const Vector3& velocityVariances, const Vector3& angularVelocityVariances) {
  Vector6 d;
  d << velocityVariances, angularVelocityVariances;
  return d.asDiagonal();
}

}  // namespace

VelocityModel3::VelocityModel3(const Matrix6& inputCovariance, const Vector6& floor)
    : inputCovariance_(inputCovariance), floor_(floor) {
  if (!inputCovariance.allFinite()) {
    throw std::invalid_argument("VelocityModel3: the input covariance has a NaN or infinite entry");
  }
  const double scale = std::max(1.0, inputCovariance.cwiseAbs().maxCoeff());
  if ((inputCovariance - inputCovariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    throw std::invalid_argument("VelocityModel3: the input covariance is not symmetric");
  }
  inputCovariance_ = 0.5 * (inputCovariance + inputCovariance.transpose());
  if (Eigen::SelfAdjointEigenSolver<Matrix6>(inputCovariance_, Eigen::EigenvaluesOnly).eigenvalues().minCoeff() <
      -1e-12 * scale) {
    throw std::invalid_argument("VelocityModel3: the input covariance is not positive semi-definite");
  }
  if (!floor.allFinite() || (floor.array() < 0.0).any()) {
    throw std::invalid_argument("VelocityModel3: every floor intensity must be finite and >= 0");
  }
}

VelocityModel3::VelocityModel3(const Vector3& velocityVariances, const Vector3& angularVelocityVariances,
                               const Vector6& floor)
    : VelocityModel3(diagonalCovariance(velocityVariances, angularVelocityVariances), floor) {}

SE3 VelocityModel3::increment(const Vector3& v, const Vector3& omega, double dt, Matrix6* Hinput) {
  if (!v.allFinite() || !omega.allFinite()) {
    throw std::invalid_argument("VelocityModel3: v and omega must be finite");
  }
  if (!std::isfinite(dt) || dt < 0.0) {
    throw std::invalid_argument("VelocityModel3: dt must be finite and >= 0, got " + std::to_string(dt));
  }
  Vector6 xi;
  xi << v * dt, omega * dt;
  const SE3 delta = SE3::Exp(xi, Hinput);
  if (Hinput) *Hinput *= dt;
  return delta;
}

Odometry VelocityModel3::integrate(const Vector3& v, const Vector3& omega, double dt) const {
  Matrix6 G;
  const SE3 delta = increment(v, omega, dt, &G);
  const Matrix6 covariance = G * inputCovariance_ * G.transpose();
  return odometryWithFloor<6>(delta, covariance, dt, floor_);
}

}  // namespace semslam
