#include "semslam/geometry/SO3.h"

#include <cmath>
#include <ostream>
#include <stdexcept>

#include <Eigen/SVD>

namespace semslam {

namespace {

// Below kSmallAngle only 0/0 needs avoiding: two-term series are exact to ~1e-19 there.  Below kSeriesAngle the
// cancellation-prone coefficients use series accurate to ~1e-16 relative.
constexpr double kSmallAngle = 1e-4;
constexpr double kSeriesAngle = 0.2;
// Log takes the axis from the symmetric part of R when cos θ is below this (θ > 3π/4).
constexpr double kLogSymmetricBranchCos = -0.70710678118654752;

// 1 - cos θ without cancellation near θ = 0.
double oneMinusCos(double c, double s) { return c >= 0.0 ? s * s / (1.0 + c) : 1.0 - c; }

// sin θ / θ and (1 - cos θ) / θ².
void rodriguesCoefficients(double theta, double theta2, double c, double s, double& A, double& B) {
  if (theta < kSmallAngle) {
    A = 1.0 - theta2 / 6.0;
    B = 0.5 - theta2 / 24.0;
  } else {
    A = s / theta;
    B = oneMinusCos(c, s) / theta2;
  }
}

// (θ - sin θ) / θ³ = Σ_k (-1)^k θ^{2k} / (2k+3)!.
double thetaMinusSinOverCube(double theta, double theta2, double s) {
  if (theta < kSeriesAngle) {
    const double t2 = theta2;
    return 1.0 / 6.0 - t2 * (1.0 / 120.0 - t2 * (1.0 / 5040.0 - t2 * (1.0 / 362880.0 - t2 / 39916800.0)));
  }
  return (theta - s) / (theta2 * theta);
}

// (1 - (θ/2) cot(θ/2)) / θ² = Σ_n 2 ζ(2n) θ^{2n-2} / (2π)^{2n} = 1/12 + θ²/720 + θ⁴/30240 + ...
// cot(θ/2) is (1 + cos θ)/sin θ or sin θ/(1 - cos θ), whichever has no cancellation; accurate up to θ = π.
double inverseJacobianCoefficient(double theta, double theta2, double c, double s) {
  if (theta < kSeriesAngle) {
    const double t2 = theta2;
    return 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 * (1.0 / 1209600.0 + t2 / 47900160.0)));
  }
  const double alpha = 0.5 * theta * (c >= 0.0 ? (1.0 + c) / s : s / (1.0 - c));
  return (1.0 - alpha) / theta2;
}

// ω^² = ω ωᵀ - θ² I.
Matrix3 hatSquared(const Vector3& w, double theta2) {
  Matrix3 W2 = w * w.transpose();
  W2.diagonal().array() -= theta2;
  return W2;
}

// Jr(ω)⁻¹ = I + ½ ω^ + D ω^², given θ = |ω|, cos θ and sin θ (shared by rightJacobianInverse and Log).
Matrix3 rightJacobianInverseFromTrig(const Vector3& omega, double theta, double theta2, double c, double s) {
  Matrix3 J = inverseJacobianCoefficient(theta, theta2, c, s) * hatSquared(omega, theta2) + 0.5 * SO3::hat(omega);
  J.diagonal().array() += 1.0;
  return J;
}

}  // namespace

SO3 SO3::fromQuaternion(const Eigen::Quaterniond& q) {
  const double n = q.norm();
  if (!(n > 0.0) || !std::isfinite(n)) {
    throw std::invalid_argument("SO3::fromQuaternion: the quaternion must be finite and nonzero");
  }
  return SO3(Eigen::Quaterniond(q.coeffs() / n).toRotationMatrix());
}

SO3 SO3::fromAxisAngle(const Vector3& axis, double angle) {
  const double n = axis.norm();
  if (!(n > 0.0) || !std::isfinite(n)) {
    throw std::invalid_argument("SO3::fromAxisAngle: the axis must be finite and nonzero");
  }
  return Exp(axis * (angle / n));
}

SO3 SO3::nearest(const Matrix3& M) {
  const Eigen::JacobiSVD<Matrix3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Matrix3& U = svd.matrixU();
  const Matrix3& V = svd.matrixV();
  const Vector3 d(1.0, 1.0, (U * V.transpose()).determinant() < 0.0 ? -1.0 : 1.0);
  const Matrix3 R = U * d.asDiagonal() * V.transpose();
  // The SVD's factors are orthonormal only to a few ε; one Newton-Schulz step R (3I - RᵀR)/2 brings R to ~ε.
  return SO3(0.5 * R * (3.0 * Matrix3::Identity() - R.transpose() * R));
}

Eigen::Quaterniond SO3::toQuaternion() const {
  Eigen::Quaterniond q(R_);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  return q;
}

SO3 SO3::Exp(const Vector3& omega, Matrix3* H) {
  const double theta2 = omega.squaredNorm();
  const double theta = std::sqrt(theta2);
  const double c = std::cos(theta), s = std::sin(theta);
  double A, B;
  rodriguesCoefficients(theta, theta2, c, s, A, B);
  const Matrix3 W = hat(omega);
  const Matrix3 W2 = hatSquared(omega, theta2);
  Matrix3 R = A * W + B * W2;
  R.diagonal().array() += 1.0;
  if (H) {
    *H = thetaMinusSinOverCube(theta, theta2, s) * W2 - B * W;
    H->diagonal().array() += 1.0;
  }
  return SO3(R);
}

Vector3 SO3::Log(const SO3& rotation, Matrix3* H) {
  const Matrix3& R = rotation.R_;
  const double c = 0.5 * (R.trace() - 1.0);
  // v = vee(R - Rᵀ)/2 = sin θ · axis.
  const Vector3 v(0.5 * (R(2, 1) - R(1, 2)), 0.5 * (R(0, 2) - R(2, 0)), 0.5 * (R(1, 0) - R(0, 1)));
  Vector3 omega;
  double theta, s;
  if (c > kLogSymmetricBranchCos) {
    // θ < 3π/4: ω = (θ / sin θ) v, with θ/sin θ = asin(s)/s = 1 + s²/6 + O(s⁴) for small s.
    s = v.norm();
    const double factor = s < kSmallAngle ? 1.0 + s * s / 6.0 : std::atan2(s, c) / s;
    theta = factor * s;
    omega = factor * v;
  } else {
    // θ ≥ 3π/4: (R + Rᵀ)/2 - cos θ I = (1 - cos θ) a aᵀ; its largest column is the best-conditioned multiple
    // of the axis a. v fixes the sign (v = sin θ a with sin θ ≥ 0).
    Matrix3 S = 0.5 * (R + R.transpose());
    S.diagonal().array() -= c;
    Eigen::Index i = 0;
    S.diagonal().maxCoeff(&i);
    Vector3 axis = S.col(i).normalized();
    s = axis.dot(v);
    if (s < 0.0) {
      axis = -axis;
      s = -s;
    }
    theta = std::atan2(s, c);
    omega = theta * axis;
  }
  if (H) *H = rightJacobianInverseFromTrig(omega, theta, theta * theta, c, s);
  return omega;
}

Matrix3 SO3::rightJacobian(const Vector3& omega) {
  const double theta2 = omega.squaredNorm();
  const double theta = std::sqrt(theta2);
  const double c = std::cos(theta), s = std::sin(theta);
  double A, B;
  rodriguesCoefficients(theta, theta2, c, s, A, B);
  Matrix3 J = thetaMinusSinOverCube(theta, theta2, s) * hatSquared(omega, theta2) - B * hat(omega);
  J.diagonal().array() += 1.0;
  return J;
}

Matrix3 SO3::rightJacobianInverse(const Vector3& omega) {
  const double theta2 = omega.squaredNorm();
  const double theta = std::sqrt(theta2);
  return rightJacobianInverseFromTrig(omega, theta, theta2, std::cos(theta), std::sin(theta));
}

std::ostream& operator<<(std::ostream& os, const SO3& R) {
  const Vector3 w = SO3::Log(R);
  return os << "SO3(" << w.x() << ", " << w.y() << ", " << w.z() << ")";
}

}  // namespace semslam
