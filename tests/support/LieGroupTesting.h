#pragma once
// Shared checks for the Lie group tests (SO2, SO3, SE2, SE3): every analytic Jacobian of a group G against
// central differences (NumericalDerivative.h), with the right perturbation x ⊕ δ = x · Exp(δ).
//
// For G of tangent dimension d = G::kDim:
//   compose, between   H1 = ∂(a∘b)/∂a, H2 = ∂(a∘b)/∂b                        (d × d each)
//   inverse            H  = ∂(a⁻¹)/∂a                                        (d × d)
//   a point action     y = act(a, p): Hgroup = ∂y/∂a (n × d), Hpoint = ∂y/∂p (n × n)
//   Log                H  = ∂Log(a)/∂a, skipped within 1e-7 of the branch cut at rotation angle π, and
//                      differenced with logStep(θ) so that a ⊕ ±h e_i stays on the same side of the cut
//   Exp                H  = ∂Exp(ξ)/∂ξ = Jr(ξ), the right Jacobian
// It also holds the group axioms and the retract/localCoordinates round trip shared by the four groups.
// All are compared with EXPECT_MATRIX_NEAR at kJacobianTol: central differences with h = 1e-6 have truncation
// error ~1e-12 and rounding error ~1e-10 relative, so 1e-7 is tight but safe.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "semslam/geometry/Matrix.h"
#include "support/MatrixAssertions.h"
#include "support/NumericalDerivative.h"

namespace semslam::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kJacobianTol = 1e-7;
/// Identities that hold up to rounding (a few ulps of results of order 1 to 10).
inline constexpr double kTol = 1e-13;
/// Seeded random inputs per randomised check.
inline constexpr int kRandomTrials = 50;

/// Signed rotation angles at which the formulas switch branches or lose digits if done naively.
inline const std::vector<double> kEdgeAngles = {0.0,        1e-10,      -1e-10,      1e-6,
                                                -1e-6,      1e-3,       -1e-3,       0.5,
                                                kPi - 1e-3, kPi - 1e-6, -kPi + 1e-3, -kPi + 1e-6};

/// Rotation angles across which the right Jacobian's implementation changes between series and closed forms.
inline const std::vector<double> kRightJacobianSweepAngles = {
    0.0, 1e-12,  1e-8, 1e-5,   9.999e-5, 1e-4,   1.0001e-4, 1e-3, 0.05,       0.1999,
    0.2, 0.2001, 0.5,  0.9999, 1.0,      1.0001, 2.0,       3.0,  kPi - 1e-6, kPi};

/// The central-difference Jacobian of f at x (f: In -> Out), with step h.
template <class Out, class In, class F>
Matrix numeric(F f, const In& x, double h = 1e-6) {
  return numericalDerivative<Out, In>(std::function<Out(const In&)>(f), x, h);
}

/// A finite-difference step that keeps Log(x ⊕ ±h e_i) on the same side of its branch cut at rotation angle π.
inline double logStep(double theta) { return std::min(1e-6, 0.1 * (kPi - std::abs(theta))); }

/// Jr(ξ) = Σ_k (-ad ξ)^k / (k+1)!, given ad ξ (for SO3, ad ω = ω^): an independent reference for rightJacobian.
template <int N>
MatrixN<N, N> rightJacobianSeries(const MatrixN<N, N>& adjointOfTangent) {
  using Square = MatrixN<N, N>;
  const Square A = -adjointOfTangent;
  Square result = Square::Identity(), term = Square::Identity();
  for (int k = 1; k < 60; ++k) {
    term = term * A / (k + 1);
    result += term;
  }
  return result;
}

/// The group axioms through G's product, to `tol`: matrix(a·b) = matrix(a)·matrix(b), a·a⁻¹ = e,
/// between(a, b) = a⁻¹·b and (a·b)·c = a·(b·c).
template <class G>
void checkGroupAxioms(const G& a, const G& b, const G& c, double tol) {
  EXPECT_MATRIX_NEAR((a * b).matrix(), a.matrix() * b.matrix(), tol);
  EXPECT_TRUE((a * a.inverse()).equals(G(), tol));
  EXPECT_TRUE(a.between(b).equals(a.inverse() * b, tol));
  EXPECT_TRUE(((a * b) * c).equals(a * (b * c), tol));
}

/// retract and localCoordinates invert each other, to `tol`: a ⊕ (b ⊖ a) = b and (a ⊕ d) ⊖ a = d.
template <class G>
void checkRetractInvertsLocalCoordinates(const G& a, const G& b, const typename G::TangentVector& d, double tol) {
  EXPECT_TRUE(a.retract(a.localCoordinates(b)).equals(b, tol));
  EXPECT_MATRIX_NEAR(a.localCoordinates(a.retract(d)), d, tol);
}

/// compose, inverse and between of G at (a, b).
template <class G>
void checkGroupOperationJacobians(const G& a, const G& b) {
  MatrixN<G::kDim, G::kDim> H1, H2, H;
  a.compose(b, &H1, &H2);
  EXPECT_MATRIX_NEAR(H1, numeric<G>([&](const G& x) { return x.compose(b); }, a), kJacobianTol);
  EXPECT_MATRIX_NEAR(H2, numeric<G>([&](const G& x) { return a.compose(x); }, b), kJacobianTol);

  a.inverse(&H);
  EXPECT_MATRIX_NEAR(H, numeric<G>([](const G& x) { return x.inverse(); }, a), kJacobianTol);

  a.between(b, &H1, &H2);
  EXPECT_MATRIX_NEAR(H1, numeric<G>([&](const G& x) { return x.between(b); }, a), kJacobianTol);
  EXPECT_MATRIX_NEAR(H2, numeric<G>([&](const G& x) { return a.between(x); }, b), kJacobianTol);
}

/// A point action of G (rotate, unrotate, transformFrom, transformTo) at (a, p), in both arguments.
template <class G, class Point, class GroupJacobian, class PointJacobian>
void checkActionJacobians(const G& a, const Point& p,
                          Point (G::*act)(const Point&, GroupJacobian*, PointJacobian*) const) {
  GroupJacobian Hgroup;
  PointJacobian Hpoint;
  (a.*act)(p, &Hgroup, &Hpoint);
  EXPECT_MATRIX_NEAR(Hgroup, numeric<Point>([&](const G& x) { return (x.*act)(p, nullptr, nullptr); }, a),
                     kJacobianTol);
  EXPECT_MATRIX_NEAR(Hpoint, numeric<Point>([&](const Point& x) { return (a.*act)(x, nullptr, nullptr); }, p),
                     kJacobianTol);
}

/// Log of G at a, whose rotation angle is theta (|θ| ≤ π); skipped next to the branch cut.
template <class G>
void checkLogJacobian(const G& a, double theta) {
  if (kPi - std::abs(theta) > 1e-7) {  // Log jumps at angle π; closer than this no finite step is usable
    MatrixN<G::kDim, G::kDim> H;
    G::Log(a, &H);
    using Tangent = typename G::TangentVector;
    EXPECT_MATRIX_NEAR(H, numeric<Tangent>([](const G& x) { return G::Log(x); }, a, logStep(theta)),
                       kJacobianTol);
  }
}

/// Exp of G at xi: its Jacobian against central differences; returns the numerical right Jacobian.
template <class G>
Matrix checkExpJacobian(const typename G::TangentVector& xi) {
  MatrixN<G::kDim, G::kDim> H;
  G::Exp(xi, &H);
  using Tangent = typename G::TangentVector;
  const Matrix numericJr = numeric<G>([](const Tangent& v) { return G::Exp(v); }, xi);
  EXPECT_MATRIX_NEAR(H, numericJr, kJacobianTol);
  return numericJr;
}

/// Exp's Jacobian, rightJacobian (both against central differences and equal to each other within
/// `exactTolerance`) and rightJacobianInverse · rightJacobian = I.
template <class G>
void checkExpAndRightJacobians(const typename G::TangentVector& xi, double exactTolerance) {
  SCOPED_TRACE(::testing::Message() << "xi = " << xi.transpose());
  MatrixN<G::kDim, G::kDim> H;
  G::Exp(xi, &H);
  const Matrix numericJr = checkExpJacobian<G>(xi);
  EXPECT_MATRIX_NEAR(G::rightJacobian(xi), numericJr, kJacobianTol);
  EXPECT_MATRIX_NEAR(G::rightJacobian(xi), H, exactTolerance);
  EXPECT_MATRIX_NEAR(G::rightJacobianInverse(xi) * G::rightJacobian(xi), (MatrixN<G::kDim, G::kDim>::Identity()),
                     1e-12);
}

}  // namespace semslam::test
