#pragma once
// SE3: rigid transformations of R³, T = (R, t), R ∈ SO(3), t ∈ R³, acting on points as p ↦ R p + t.
//
// Math and conventions
//   Homogeneous matrix [R t; 0 1].  Tangent vector ξ = (ρ, φ) = (ρ_x, ρ_y, ρ_z, φ_x, φ_y, φ_z): translation
//   first (the same order as Barfoot, "State Estimation for Robotics"); hat(ξ) = [φ^ ρ; 0 0].
//   Exp is the exact group exponential:  Exp(ξ) = (Exp_SO3(φ), V(φ) ρ) with V(φ) = Jl(φ) = Jr(φ)ᵀ (see SO3.h).
//   Log inverts it:  φ = Log_SO3(R) (|φ| ≤ π),  ρ = V(φ)⁻¹ t.
//   Right perturbation:  T ⊕ δ = T · Exp(δ),  y ⊖ x = Log(x⁻¹ · y).  Every Jacobian is the derivative of the
//   output's right-perturbation tangent with respect to right perturbations of the inputs:
//       f(x ⊕ δ) = f(x) ⊕ (H δ + O(|δ|²))   (for point outputs, ⊕ is +).
//   Adjoint (translation first):  T · Exp(ξ) = Exp(Ad_T ξ) · T,   Ad_T = [R  t^R; 0  R].
//   Right Jacobian:  Exp(ξ + δ) = Exp(ξ) · Exp(Jr(ξ) δ + O(|δ|²)),
//       Jr(ξ)   = [Jr(φ)  Q(-ρ, -φ); 0  Jr(φ)],
//       Jr(ξ)⁻¹ = [Jr(φ)⁻¹  -Jr(φ)⁻¹ Q(-ρ, -φ) Jr(φ)⁻¹; 0  Jr(φ)⁻¹],
//   where Q(ρ, φ) is the off-diagonal block of the left Jacobian (Barfoot eq. 7.86; Jr(ξ) = Jl(-ξ)):
//       Q = ½ ρ^ + c1 (φ^ρ^ + ρ^φ^ + φ^ρ^φ^) + c2 (φ^φ^ρ^ + ρ^φ^φ^ - 3 φ^ρ^φ^)
//             + c3 (φ^ρ^φ^φ^ + φ^φ^ρ^φ^),
//       c1 = (θ - sin θ)/θ³,  c2 = (θ² + 2 cos θ - 2)/(2θ⁴),  c3 = (2θ - 3 sin θ + θ cos θ)/(2θ⁵),  θ = |φ|.
//   Jr(ξ)⁻¹ is singular at |φ| = 2π; Log never produces such φ.
//
// Numerics
//   c1, c2, c3 use Taylor series for small θ (each is a difference of O(θ) terms that cancel to O(θ^k)); the
//   SO(3) parts inherit SO3's small-angle and near-π handling, so Exp, Log and both Jacobians are accurate at
//   θ = 0, at tiny θ and up to θ = π.  compose, inverse, between and the actions are inline: they are the
//   solver's inner loop for 3D problems.

#include <iosfwd>

#include "semslam/geometry/Matrix.h"
#include "semslam/geometry/SO3.h"

namespace semslam {

class SE3 {
 public:
  static constexpr int kDim = 6;
  using TangentVector = Vector6;

  /// Identity.
  SE3() = default;
  SE3(const SO3& R, const Point3& t) : R_(R), t_(t) {}

  const SO3& rotation() const { return R_; }
  const Point3& translation() const { return t_; }
  /// Homogeneous 4x4 matrix [R t; 0 1].
  Matrix4 matrix() const {
    Matrix4 M = Matrix4::Identity();
    M.topLeftCorner<3, 3>() = R_.matrix();
    M.topRightCorner<3, 1>() = t_;
    return M;
  }

  /// this · other = (R1 R2, t1 + R1 t2).  H1 = Ad(other⁻¹),  H2 = I.
  SE3 compose(const SE3& other, Matrix6* H1 = nullptr, Matrix6* H2 = nullptr) const {
    if (H1) *H1 = other.inverseAdjoint();
    if (H2) H2->setIdentity();
    return SE3(R_ * other.R_, t_ + R_.matrix() * other.t_);
  }
  SE3 operator*(const SE3& other) const { return compose(other); }

  /// this⁻¹ = (Rᵀ, -Rᵀ t).  H = -Ad(this).
  SE3 inverse(Matrix6* H = nullptr) const {
    if (H) *H = -adjoint();
    return SE3(R_.inverse(), -(R_.matrix().transpose() * t_));
  }

  /// this⁻¹ · other.  H1 = -Ad((this⁻¹ · other)⁻¹),  H2 = I.
  SE3 between(const SE3& other, Matrix6* H1 = nullptr, Matrix6* H2 = nullptr) const {
    const SE3 d(R_.between(other.R_), R_.matrix().transpose() * (other.t_ - t_));
    if (H1) *H1 = -d.inverseAdjoint();
    if (H2) H2->setIdentity();
    return d;
  }

  /// q = R p + t (the group action).  Hpose = [R, -R p^],  Hpoint = R.
  Point3 transformFrom(const Point3& p, Matrix36* Hpose = nullptr, Matrix3* Hpoint = nullptr) const {
    const Matrix3& R = R_.matrix();
    if (Hpose) {
      Hpose->leftCols<3>() = R;
      Hpose->rightCols<3>() = -R * SO3::hat(p);
    }
    if (Hpoint) *Hpoint = R;
    return R * p + t_;
  }

  /// q = Rᵀ (p - t) (the inverse action).  Hpose = [-I, q^],  Hpoint = Rᵀ.
  Point3 transformTo(const Point3& p, Matrix36* Hpose = nullptr, Matrix3* Hpoint = nullptr) const {
    const Point3 q = R_.matrix().transpose() * (p - t_);
    if (Hpose) {
      Hpose->leftCols<3>() = -Matrix3::Identity();
      Hpose->rightCols<3>() = SO3::hat(q);
    }
    if (Hpoint) *Hpoint = R_.matrix().transpose();
    return q;
  }

  /// Exact exponential (Exp(φ), V(φ) ρ).  H = Jr(ξ).
  static SE3 Exp(const Vector6& xi, Matrix6* H = nullptr);
  /// Inverse of Exp: φ = Log(R) with |φ| ≤ π, ρ = V(φ)⁻¹ t.  H = Jr⁻¹(Log T).
  static Vector6 Log(const SE3& T, Matrix6* H = nullptr);
  /// Jr(ξ), see the header comment.
  static Matrix6 rightJacobian(const Vector6& xi);
  /// Jr(ξ)⁻¹ in closed form; defined for |φ| < 2π.
  static Matrix6 rightJacobianInverse(const Vector6& xi);

  /// Ad_T = [R t^R; 0 R], so that T · Exp(ξ) = Exp(Ad_T ξ) · T.
  Matrix6 adjoint() const {
    const Matrix3& R = R_.matrix();
    Matrix6 A;
    A.topLeftCorner<3, 3>() = R;
    A.topRightCorner<3, 3>() = SO3::hat(t_) * R;
    A.bottomLeftCorner<3, 3>().setZero();
    A.bottomRightCorner<3, 3>() = R;
    return A;
  }

  /// this · Exp(delta).
  SE3 retract(const Vector6& delta) const { return compose(Exp(delta)); }
  /// Log(this⁻¹ · y).
  Vector6 localCoordinates(const SE3& y) const { return Log(between(y)); }

  /// this · Exp(t · Log(this⁻¹ · other)): constant-twist (screw) motion, t = 0 gives this, t = 1 gives other.
  SE3 interpolate(const SE3& other, double t) const { return compose(Exp(t * Log(between(other)))); }

  /// True when rotation matrices and translations agree entry-wise within tol.
  bool equals(const SE3& other, double tol = 1e-9) const {
    return R_.equals(other.R_, tol) && (t_ - other.t_).cwiseAbs().maxCoeff() <= tol;
  }

 private:
  // Ad(this⁻¹) = [Rᵀ  -Rᵀ t^; 0  Rᵀ], without forming the inverse.
  Matrix6 inverseAdjoint() const {
    const Matrix3 Rt = R_.matrix().transpose();
    Matrix6 A;
    A.topLeftCorner<3, 3>() = Rt;
    A.topRightCorner<3, 3>() = -Rt * SO3::hat(t_);
    A.bottomLeftCorner<3, 3>().setZero();
    A.bottomRightCorner<3, 3>() = Rt;
    return A;
  }

  SO3 R_;
  Point3 t_ = Point3::Zero();
};

/// Prints "SE3(t: x y z, R: ωx ωy ωz)" with the rotation as a rotation vector.
std::ostream& operator<<(std::ostream& os, const SE3& T);

}  // namespace semslam
