#pragma once
// SO3: rotations of R³, stored as the 3x3 rotation matrix R.
//
// Math and conventions
//   hat(ω) = ω^ = [0 -ω_z ω_y; ω_z 0 -ω_x; -ω_y ω_x 0], so ω^ v = ω × v;  vee is its inverse.
//   Exp(ω) = I + (sin θ/θ) ω^ + ((1 - cos θ)/θ²) ω^²,  θ = |ω|  (Rodrigues).
//   Log(R) = ω with |ω| = θ ∈ [0, π]; at θ = π exactly, either of the two opposite axes may be returned.
//   Right perturbation:  R ⊕ δ = R · Exp(δ),  y ⊖ x = Log(x⁻¹ · y).  Every Jacobian is the derivative of the
//   output's right-perturbation tangent with respect to right perturbations of the inputs:
//       f(x ⊕ δ) = f(x) ⊕ (H δ + O(|δ|²))   (for point outputs, ⊕ is +).
//   Adjoint: R · Exp(ω) = Exp(R ω) · R, so Ad_R = R.
//   Right Jacobian:  Exp(ω + δ) = Exp(ω) · Exp(Jr(ω) δ + O(|δ|²)),
//       Jr(ω)   = I - ((1 - cos θ)/θ²) ω^ + ((θ - sin θ)/θ³) ω^²,
//       Jr(ω)⁻¹ = I + ½ ω^ + ((1 - (θ/2) cot(θ/2))/θ²) ω^²     (singular at θ = 2π).
//   The left Jacobian is Jl(ω) = Jr(-ω) = Jr(ω)ᵀ (it is the V matrix of SE(3)).
//
// Numerics
//   Near θ = 0 all coefficients use Taylor series (no 0/0; no cancellation in (θ - sin θ)/θ³ or in
//   1 - (θ/2)cot(θ/2)).  Log uses θ = atan2(|v|, (tr R - 1)/2) with v = vee(R - Rᵀ)/2 = sin θ · axis; for
//   θ > 3π/4 the axis is taken from the symmetric part (R + Rᵀ)/2 - cos θ I = (1 - cos θ) axis axisᵀ (its
//   largest column), with the sign from v, which keeps full accuracy up to and at θ = π.
//
// Invariants
//   R is orthonormal with det +1 up to rounding.  The Matrix3 constructor trusts its argument (use nearest() for
//   matrices that are only approximately orthonormal, e.g. read from text files).  compose does not
//   re-orthonormalise; drift after n compositions is O(n·ε).

#include <iosfwd>

#include <Eigen/Geometry>

#include "semslam/geometry/Matrix.h"

namespace semslam {

class SO3 {
 public:
  static constexpr int kDim = 3;
  using TangentVector = Vector3;

  /// Identity.
  SO3() : R_(Matrix3::Identity()) {}
  /// From a rotation matrix, assumed orthonormal with det +1 (not checked).
  explicit SO3(const Matrix3& R) : R_(R) {}
  /// From a quaternion, which is normalised first; q and -q give the same rotation. Throws
  /// std::invalid_argument for a zero or non-finite quaternion.
  static SO3 fromQuaternion(const Eigen::Quaterniond& q);
  /// Rotation by `angle` radians about `axis` (normalised first; any nonzero length). A zero axis gives
  /// std::invalid_argument.
  static SO3 fromAxisAngle(const Vector3& axis, double angle);
  /// The rotation closest to M in the Frobenius norm (SVD projection with det +1).
  static SO3 nearest(const Matrix3& M);

  /// Unit quaternion with w ≥ 0.
  Eigen::Quaterniond toQuaternion() const;
  const Matrix3& matrix() const { return R_; }

  /// this · other.  H1 = otherᵀ,  H2 = I.
  SO3 compose(const SO3& other, Matrix3* H1 = nullptr, Matrix3* H2 = nullptr) const {
    if (H1) *H1 = other.R_.transpose();
    if (H2) H2->setIdentity();
    return SO3(R_ * other.R_);
  }
  SO3 operator*(const SO3& other) const { return compose(other); }

  /// Rᵀ.  H = -R.
  SO3 inverse(Matrix3* H = nullptr) const {
    if (H) *H = -R_;
    return SO3(R_.transpose());
  }

  /// thisᵀ · other.  H1 = -(thisᵀ other)ᵀ,  H2 = I.
  SO3 between(const SO3& other, Matrix3* H1 = nullptr, Matrix3* H2 = nullptr) const {
    SO3 d(R_.transpose() * other.R_);
    if (H1) *H1 = -d.R_.transpose();
    if (H2) H2->setIdentity();
    return d;
  }

  /// R p.  Hrot = -R p^,  Hp = R.
  Point3 rotate(const Point3& p, Matrix3* Hrot = nullptr, Matrix3* Hp = nullptr) const {
    if (Hrot) *Hrot = -R_ * hat(p);
    if (Hp) *Hp = R_;
    return R_ * p;
  }

  /// q = Rᵀ p.  Hrot = q^,  Hp = Rᵀ.
  Point3 unrotate(const Point3& p, Matrix3* Hrot = nullptr, Matrix3* Hp = nullptr) const {
    const Point3 q = R_.transpose() * p;
    if (Hrot) *Hrot = hat(q);
    if (Hp) *Hp = R_.transpose();
    return q;
  }

  /// Rodrigues' formula.  H = Jr(ω).
  static SO3 Exp(const Vector3& omega, Matrix3* H = nullptr);
  /// Inverse of Exp with |ω| ∈ [0, π].  H = Jr⁻¹(Log R).
  static Vector3 Log(const SO3& R, Matrix3* H = nullptr);
  /// Jr(ω), see the header comment.
  static Matrix3 rightJacobian(const Vector3& omega);
  /// Jr(ω)⁻¹ in closed form; defined for |ω| < 2π.
  static Matrix3 rightJacobianInverse(const Vector3& omega);

  /// ω^, the skew-symmetric matrix with ω^ v = ω × v.
  static Matrix3 hat(const Vector3& w) {
    Matrix3 W;
    W << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
    return W;
  }
  /// (W(2,1), W(0,2), W(1,0)): the inverse of hat for skew-symmetric W (other entries are ignored).
  static Vector3 vee(const Matrix3& W) { return Vector3(W(2, 1), W(0, 2), W(1, 0)); }

  /// Ad_R = R: R · Exp(ω) = Exp(R ω) · R.
  Matrix3 adjoint() const { return R_; }

  /// this · Exp(delta).
  SO3 retract(const Vector3& delta) const { return compose(Exp(delta)); }
  /// Log(this⁻¹ · y).
  Vector3 localCoordinates(const SO3& y) const { return Log(between(y)); }

  /// this · Exp(t · Log(this⁻¹ · other)): the shortest geodesic (slerp), t = 0 gives this, t = 1 gives other.
  SO3 interpolate(const SO3& other, double t) const { return compose(Exp(t * Log(between(other)))); }

  /// True when the matrices agree entry-wise within tol.
  bool equals(const SO3& other, double tol = 1e-9) const {
    return (R_ - other.R_).cwiseAbs().maxCoeff() <= tol;
  }

 private:
  Matrix3 R_;
};

/// Prints the rotation vector: "SO3(ωx, ωy, ωz)".
std::ostream& operator<<(std::ostream& os, const SO3& R);

}  // namespace semslam
