#pragma once
// SO2: planar rotations, stored as the unit complex number (c, s) = (cos θ, sin θ).
//
// Math and conventions
//   R(θ) = [c -s; s c].  The Lie algebra so(2) is the scalar θ with hat(θ) = [0 -θ; θ 0].
//   Exp(θ) = R(θ);  Log(R) = atan2(s, c), returned in (-π, π].
//   Right perturbation (as everywhere in semslam):  R ⊕ δ = R · Exp(δ),  y ⊖ x = Log(x⁻¹ · y).
//   Every Jacobian is the derivative of the output's right-perturbation tangent with respect to the right
//   perturbations of the inputs, i.e.  f(x ⊕ δ) = f(x) ⊕ (H δ + O(|δ|²)).
//   SO(2) is abelian, so the adjoint is 1, Jr = Jr⁻¹ = 1, and compose/between Jacobians are ±1.
//
// Invariants
//   c² + s² = 1 up to rounding.  Constructors and Exp produce unit (c, s); compose, inverse and between do not
//   re-normalise (the drift after n compositions is O(n·ε), irrelevant in practice); fromCosSin normalises.
//
// Every member is cheap and inline except the few that are not on a solver's hot path.

#include <cmath>
#include <iosfwd>
#include <numbers>

#include "semslam/geometry/Matrix.h"

namespace semslam {

class SO2 {
 public:
  static constexpr int kDim = 1;
  using TangentVector = Vector1;

  /// Identity rotation.
  SO2() = default;
  /// Rotation by `theta` radians (any real value; it is wrapped by cos/sin).
  explicit SO2(double theta) : c_(std::cos(theta)), s_(std::sin(theta)) {}
  /// Rotation with cos θ ∝ c and sin θ ∝ s; (c, s) is normalised. Throws std::invalid_argument if (c, s) is zero
  /// or not finite.
  static SO2 fromCosSin(double c, double s);

  /// The angle in (-π, π] (same as Log).
  double theta() const {
    const double t = std::atan2(s_, c_);
    return t == -std::numbers::pi ? std::numbers::pi : t;  // atan2(-0.0, c < 0) gives -π; the range is (-π, π]
  }
  double c() const { return c_; }
  double s() const { return s_; }
  Matrix2 matrix() const {
    Matrix2 R;
    R << c_, -s_, s_, c_;
    return R;
  }

  /// this · other.  H1 = H2 = 1.
  SO2 compose(const SO2& other, Matrix1* H1 = nullptr, Matrix1* H2 = nullptr) const {
    if (H1) H1->setOnes();
    if (H2) H2->setOnes();
    return SO2(c_ * other.c_ - s_ * other.s_, s_ * other.c_ + c_ * other.s_, Raw{});
  }
  SO2 operator*(const SO2& other) const { return compose(other); }

  /// this⁻¹.  H = -1.
  SO2 inverse(Matrix1* H = nullptr) const {
    if (H) H->setConstant(-1.0);
    return SO2(c_, -s_, Raw{});
  }

  /// this⁻¹ · other.  H1 = -1, H2 = 1.
  SO2 between(const SO2& other, Matrix1* H1 = nullptr, Matrix1* H2 = nullptr) const {
    if (H1) H1->setConstant(-1.0);
    if (H2) H2->setOnes();
    return SO2(c_ * other.c_ + s_ * other.s_, c_ * other.s_ - s_ * other.c_, Raw{});
  }

  /// q = R p.  Hrot = R·hat(1)·p = [-q_y; q_x],  Hp = R.
  Point2 rotate(const Point2& p, MatrixN<2, 1>* Hrot = nullptr, Matrix2* Hp = nullptr) const {
    const Point2 q(c_ * p.x() - s_ * p.y(), s_ * p.x() + c_ * p.y());
    if (Hrot) *Hrot << -q.y(), q.x();
    if (Hp) *Hp = matrix();
    return q;
  }

  /// q = Rᵀ p.  Hrot = -hat(1)·q = [q_y; -q_x],  Hp = Rᵀ.
  Point2 unrotate(const Point2& p, MatrixN<2, 1>* Hrot = nullptr, Matrix2* Hp = nullptr) const {
    const Point2 q(c_ * p.x() + s_ * p.y(), -s_ * p.x() + c_ * p.y());
    if (Hrot) *Hrot << q.y(), -q.x();
    if (Hp) *Hp = matrix().transpose();
    return q;
  }

  /// Exp(θ) = R(θ).  H = Jr = 1.
  static SO2 Exp(const Vector1& theta, Matrix1* H = nullptr) {
    if (H) H->setOnes();
    return SO2(theta(0));
  }

  /// Log(R) = θ ∈ (-π, π].  H = Jr⁻¹ = 1.
  static Vector1 Log(const SO2& R, Matrix1* H = nullptr) {
    if (H) H->setOnes();
    return Vector1(R.theta());
  }

  /// this · Exp(delta).
  SO2 retract(const Vector1& delta) const { return compose(Exp(delta)); }
  /// Log(this⁻¹ · y) ∈ (-π, π].
  Vector1 localCoordinates(const SO2& y) const { return Log(between(y)); }

  /// R · Exp(ξ) = Exp(Ad ξ) · R with Ad = 1.
  Matrix1 adjoint() const { return Matrix1::Ones(); }

  /// this · Exp(t · Log(this⁻¹ · other)): the shortest arc, t = 0 gives this and t = 1 gives other. When the two
  /// are exactly π apart the arc turns counter-clockwise (Log returns +π).
  SO2 interpolate(const SO2& other, double t) const { return compose(SO2(t * between(other).theta())); }

  /// True when the two rotation matrices agree entry-wise within tol.
  bool equals(const SO2& other, double tol = 1e-9) const {
    return std::abs(c_ - other.c_) <= tol && std::abs(s_ - other.s_) <= tol;
  }

 private:
  struct Raw {};
  SO2(double c, double s, Raw) : c_(c), s_(s) {}

  double c_ = 1.0;
  double s_ = 0.0;
};

/// Prints "SO2(theta)".
std::ostream& operator<<(std::ostream& os, const SO2& R);

}  // namespace semslam
