#pragma once
// SE2: planar rigid transformations T = (R, t), R ∈ SO(2), t ∈ R², acting on points as p ↦ R p + t.
//
// Math and conventions
//   Homogeneous matrix [R t; 0 1].  Tangent vector ξ = (ρ_x, ρ_y, θ): translation first, as the papers write
//   their covariances; hat(ξ) = [θ^ ρ; 0 0] with θ^ = [0 -θ; θ 0].
//   Exp is the exact group exponential (not a first-order chart):
//       Exp(ξ) = (R(θ), V(θ) ρ),   V(θ) = [A -B; B A],   A = sin θ / θ,   B = (1 - cos θ) / θ.
//   Log inverts it with θ ∈ (-π, π] and ρ = V(θ)⁻¹ t,  V⁻¹ = [α θ/2; -θ/2 α],  α = (θ/2) cot(θ/2).
//   Right perturbation:  T ⊕ δ = T · Exp(δ),  y ⊖ x = Log(x⁻¹ · y).  Every Jacobian is the derivative of the
//   output's right-perturbation tangent with respect to right perturbations of the inputs:
//       f(x ⊕ δ) = f(x) ⊕ (H δ + O(|δ|²))   (for point outputs, ⊕ is +).
//   Adjoint (translation first):  T · Exp(ξ) = Exp(Ad_T ξ) · T,   Ad_T = [R  (t_y, -t_x)ᵀ; 0 1].
//   Right Jacobian Jr(ξ):  Exp(ξ + δ) = Exp(ξ) · Exp(Jr(ξ) δ + O(|δ|²));  Jr⁻¹(Log T) is the Jacobian of Log.
//       Jr(ξ) = [ A  B  ρ_x D - ρ_y C ]      C = (1 - cos θ) / θ²,  D = (θ - sin θ) / θ²
//               [-B  A  ρ_x C + ρ_y D ]
//               [ 0  0  1             ]
//       Jr⁻¹(ξ) = [ α    -θ/2  e ρ_x + ρ_y/2 ]   e = (1 - α) / θ
//                 [ θ/2   α   -ρ_x/2 + e ρ_y ]
//                 [ 0     0    1             ]
//   Jr⁻¹ is singular at |θ| = 2π; Log never produces such θ.
//
// Numerics
//   Near θ = 0 the coefficients use Taylor series (no 0/0, no cancellation); 1 - cos θ is evaluated as
//   sin²θ / (1 + cos θ) where that avoids cancellation, cot(θ/2) as (1 + cos θ)/sin θ or sin θ/(1 - cos θ),
//   whichever is accurate, so Log is accurate up to θ = π.  Everything here is inline: these are the solver's
//   inner loop for 2D problems.

#include <cmath>
#include <iosfwd>

#include "semslam/geometry/Matrix.h"
#include "semslam/geometry/SO2.h"

namespace semslam {

class SE2 {
 public:
  static constexpr int kDim = 3;
  using TangentVector = Vector3;

  /// Identity.
  SE2() = default;
  /// Rotation by theta, then translation (x, y): p ↦ R(θ) p + (x, y).
  SE2(double x, double y, double theta) : R_(theta), t_(x, y) {}
  SE2(const SO2& R, const Point2& t) : R_(R), t_(t) {}

  double x() const { return t_.x(); }
  double y() const { return t_.y(); }
  /// Heading in (-π, π].
  double theta() const { return R_.theta(); }
  const Point2& translation() const { return t_; }
  const SO2& rotation() const { return R_; }
  /// Homogeneous 3x3 matrix [R t; 0 1].
  Matrix3 matrix() const {
    Matrix3 M;
    M << R_.c(), -R_.s(), t_.x(), R_.s(), R_.c(), t_.y(), 0.0, 0.0, 1.0;
    return M;
  }

  /// this · other = (R1 R2, t1 + R1 t2).  H1 = Ad(other⁻¹),  H2 = I.
  SE2 compose(const SE2& other, Matrix3* H1 = nullptr, Matrix3* H2 = nullptr) const {
    if (H1) *H1 = other.inverseAdjoint();
    if (H2) H2->setIdentity();
    return SE2(R_ * other.R_, t_ + R_.rotate(other.t_));
  }
  SE2 operator*(const SE2& other) const { return compose(other); }

  /// this⁻¹ = (Rᵀ, -Rᵀ t).  H = -Ad(this).
  SE2 inverse(Matrix3* H = nullptr) const {
    if (H) *H = -adjoint();
    return SE2(R_.inverse(), -R_.unrotate(t_));
  }

  /// this⁻¹ · other.  H1 = -Ad((this⁻¹ · other)⁻¹),  H2 = I.
  SE2 between(const SE2& other, Matrix3* H1 = nullptr, Matrix3* H2 = nullptr) const {
    const SE2 d(R_.between(other.R_), R_.unrotate(other.t_ - t_));
    if (H1) *H1 = -d.inverseAdjoint();
    if (H2) H2->setIdentity();
    return d;
  }

  /// q = R p + t (the group action).  Hpose = [R, R·hat(1)·p],  Hpoint = R.
  Point2 transformFrom(const Point2& p, Matrix23* Hpose = nullptr, Matrix2* Hpoint = nullptr) const {
    const Point2 Rp = R_.rotate(p);
    if (Hpose) *Hpose << R_.c(), -R_.s(), -Rp.y(), R_.s(), R_.c(), Rp.x();
    if (Hpoint) *Hpoint = R_.matrix();
    return Rp + t_;
  }

  /// q = Rᵀ (p - t) (the inverse action).  Hpose = [-I, (q_y, -q_x)ᵀ],  Hpoint = Rᵀ.
  Point2 transformTo(const Point2& p, Matrix23* Hpose = nullptr, Matrix2* Hpoint = nullptr) const {
    const Point2 q = R_.unrotate(p - t_);
    if (Hpose) *Hpose << -1.0, 0.0, q.y(), 0.0, -1.0, -q.x();
    if (Hpoint) *Hpoint = R_.matrix().transpose();
    return q;
  }

  /// Exact exponential (R(θ), V(θ) ρ).  H = Jr(ξ).
  static SE2 Exp(const Vector3& xi, Matrix3* H = nullptr) {
    const double theta = xi(2);
    const SO2 R(theta);
    const Coefficients k = coefficients(theta, R.c(), R.s());
    const Point2 t(k.A * xi(0) - k.B * xi(1), k.B * xi(0) + k.A * xi(1));
    if (H) *H = rightJacobian(xi, k);
    return SE2(R, t);
  }

  /// Inverse of Exp: θ ∈ (-π, π], ρ = V(θ)⁻¹ t.  H = Jr⁻¹(Log T).
  static Vector3 Log(const SE2& T, Matrix3* H = nullptr) {
    const double theta = T.theta();
    const double alpha = halfCot(theta, T.R_.c(), T.R_.s());
    const double h = 0.5 * theta;
    const Point2& t = T.t_;
    const Vector3 xi(alpha * t.x() + h * t.y(), -h * t.x() + alpha * t.y(), theta);
    if (H) *H = rightJacobianInverse(xi, alpha);
    return xi;
  }

  /// Jr(ξ), see the header comment.
  static Matrix3 rightJacobian(const Vector3& xi) {
    const double theta = xi(2);
    return rightJacobian(xi, coefficients(theta, std::cos(theta), std::sin(theta)));
  }

  /// Jr(ξ)⁻¹ in closed form; defined for |θ| < 2π.
  static Matrix3 rightJacobianInverse(const Vector3& xi) {
    const double theta = xi(2);
    return rightJacobianInverse(xi, halfCot(theta, std::cos(theta), std::sin(theta)));
  }

  /// Ad_T = [R (t_y, -t_x)ᵀ; 0 1], so that T · Exp(ξ) = Exp(Ad_T ξ) · T.
  Matrix3 adjoint() const {
    Matrix3 A;
    A << R_.c(), -R_.s(), t_.y(), R_.s(), R_.c(), -t_.x(), 0.0, 0.0, 1.0;
    return A;
  }

  /// this · Exp(delta).
  SE2 retract(const Vector3& delta) const { return compose(Exp(delta)); }
  /// Log(this⁻¹ · y).
  Vector3 localCoordinates(const SE2& y) const { return Log(between(y)); }

  /// this · Exp(t · Log(this⁻¹ · other)): constant-twist (screw) motion, t = 0 gives this, t = 1 gives other.
  /// The translation follows an arc, not a straight line, unless the headings agree.
  SE2 interpolate(const SE2& other, double t) const { return compose(Exp(t * Log(between(other)))); }

  /// True when rotation (cos, sin) and translation agree entry-wise within tol.
  bool equals(const SE2& other, double tol = 1e-9) const {
    return R_.equals(other.R_, tol) && (t_ - other.t_).cwiseAbs().maxCoeff() <= tol;
  }

 private:
  // Coefficients of V(θ) and Jr(ξ) (see the header comment).
  struct Coefficients {
    double A, B, C, D;
  };

  // Below kSmallAngle only 0/0 needs avoiding: two-term series are exact to ~1e-19.  Below kSeriesAngle the
  // cancellation-prone (θ - sin θ)/θ² and (1 - α)/θ use series accurate to ~1e-16 relative.
  static constexpr double kSmallAngle = 1e-4;
  static constexpr double kSeriesAngle = 0.2;

  static Coefficients coefficients(double theta, double c, double s) {
    Coefficients k;
    const double t2 = theta * theta;
    if (std::abs(theta) < kSmallAngle) {
      k.A = 1.0 - t2 / 6.0;
      k.C = 0.5 - t2 / 24.0;
    } else {
      const double oneMinusCos = c >= 0.0 ? s * s / (1.0 + c) : 1.0 - c;
      k.A = s / theta;
      k.C = oneMinusCos / t2;
    }
    k.B = theta * k.C;
    if (std::abs(theta) < kSeriesAngle) {
      // (θ - sin θ)/θ³ = Σ_k (-1)^k θ^{2k} / (2k+3)!
      k.D = theta * (1.0 / 6.0 -
                     t2 * (1.0 / 120.0 - t2 * (1.0 / 5040.0 - t2 * (1.0 / 362880.0 - t2 / 39916800.0))));
    } else {
      k.D = (theta - s) / t2;
    }
    return k;
  }

  // α = (θ/2) cot(θ/2), using whichever of (1 + cos θ)/sin θ and sin θ/(1 - cos θ) is free of cancellation.
  static double halfCot(double theta, double c, double s) {
    if (std::abs(theta) < kSmallAngle) return 1.0 - theta * theta / 12.0;
    return 0.5 * theta * (c >= 0.0 ? (1.0 + c) / s : s / (1.0 - c));
  }

  static Matrix3 rightJacobian(const Vector3& xi, const Coefficients& k) {
    const double px = xi(0), py = xi(1);
    Matrix3 J;
    J << k.A, k.B, px * k.D - py * k.C,  //
        -k.B, k.A, px * k.C + py * k.D,  //
        0.0, 0.0, 1.0;
    return J;
  }

  static Matrix3 rightJacobianInverse(const Vector3& xi, double alpha) {
    const double theta = xi(2), px = xi(0), py = xi(1);
    double e;  // (1 - α)/θ = θ · Σ 2ζ(2n) θ^{2n-2} / (2π)^{2n}
    if (std::abs(theta) < kSeriesAngle) {
      const double t2 = theta * theta;
      e = theta * (1.0 / 12.0 +
                   t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 * (1.0 / 1209600.0 + t2 / 47900160.0))));
    } else {
      e = (1.0 - alpha) / theta;
    }
    const double h = 0.5 * theta;
    Matrix3 J;
    J << alpha, -h, e * px + 0.5 * py,  //
        h, alpha, -0.5 * px + e * py,   //
        0.0, 0.0, 1.0;
    return J;
  }

  // Ad(this⁻¹) = [Rᵀ  (-w_y, w_x)ᵀ; 0 1] with w = Rᵀ t, without forming the inverse.
  Matrix3 inverseAdjoint() const {
    const Point2 w = R_.unrotate(t_);
    Matrix3 A;
    A << R_.c(), R_.s(), -w.y(), -R_.s(), R_.c(), w.x(), 0.0, 0.0, 1.0;
    return A;
  }

  SO2 R_;
  Point2 t_ = Point2::Zero();
};

/// Prints "SE2(x, y, theta)".
std::ostream& operator<<(std::ostream& os, const SE2& T);

}  // namespace semslam
