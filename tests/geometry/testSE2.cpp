// Tests of SE2: group identities, the exact exponential (against a matrix exponential), Log near ±π, the right
// Jacobian and its inverse (against the series Σ (-ad)^k/(k+1)!), and every analytic Jacobian against central
// differences (tests/support/NumericalDerivative.h) on seeded random inputs and on edge-case angles.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include <Eigen/Dense>

#include "semslam/geometry/SE2.h"
#include "support/LieGroupTesting.h"
#include "support/MatrixExponential.h"
#include "support/RandomGeometry.h"

namespace semslam {
namespace {

using namespace test;  // kPi, kTol, kRandomTrials, kEdgeAngles, the Jacobian checks, EXPECT_MATRIX_NEAR

struct Random : RandomPlane {
  Random() : RandomPlane(20240612u) {}
  SE2 pose() {
    const Point2 t = point();
    return SE2(SO2(angle()), t);
  }
  Vector3 tangent(double theta) {
    const Point2 rho = point();
    return Vector3(rho.x(), rho.y(), theta);
  }
};

Matrix3 hat(const Vector3& xi) {
  Matrix3 X;
  X << 0.0, -xi(2), xi(0), xi(2), 0.0, xi(1), 0.0, 0.0, 0.0;
  return X;
}

// ad(ξ) with ad(ξ) η = vee([hat ξ, hat η]), translation first.
Matrix3 ad(const Vector3& xi) {
  Matrix3 A;
  A << 0.0, -xi(2), xi(1), xi(2), 0.0, -xi(0), 0.0, 0.0, 0.0;
  return A;
}

void checkJacobians(const SE2& a, const SE2& b, const Point2& p) {
  SCOPED_TRACE(::testing::Message() << "a = " << a << ", b = " << b << ", p = " << p.transpose());
  checkGroupOperationJacobians(a, b);
  checkActionJacobians(a, p, &SE2::transformFrom);
  checkActionJacobians(a, p, &SE2::transformTo);
  checkLogJacobian(a, a.theta());
}

void checkExpJacobians(const Vector3& xi) { checkExpAndRightJacobians<SE2>(xi, 0.0); }

TEST(SE2Test, ConstructionAndAccessors) {
  const SE2 T(1.0, -2.0, 0.4);
  EXPECT_DOUBLE_EQ(T.x(), 1.0);
  EXPECT_DOUBLE_EQ(T.y(), -2.0);
  EXPECT_DOUBLE_EQ(T.theta(), 0.4);
  EXPECT_MATRIX_NEAR(T.translation(), Point2(1.0, -2.0), 0.0);
  EXPECT_TRUE(T.rotation().equals(SO2(0.4), 0.0));
  EXPECT_TRUE(SE2(SO2(0.4), Point2(1.0, -2.0)).equals(T, 0.0));
  Matrix3 M;
  M << std::cos(0.4), -std::sin(0.4), 1.0, std::sin(0.4), std::cos(0.4), -2.0, 0.0, 0.0, 1.0;
  EXPECT_MATRIX_NEAR(T.matrix(), M, kTol);
  EXPECT_MATRIX_NEAR(SE2().matrix(), Matrix3::Identity(), 0.0);
  EXPECT_EQ(SE2::kDim, 3);
  std::ostringstream os;
  os << SE2(1.5, -2, 0.25);
  EXPECT_EQ(os.str(), "SE2(1.5, -2, 0.25)");
}

TEST(SE2Test, GroupIdentities) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE2 a = random.pose(), b = random.pose(), c = random.pose();
    const Point2 p = random.point();
    checkGroupAxioms(a, b, c, kTol);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().inverse(), kTol);
    EXPECT_TRUE((a * a.between(b)).equals(b, kTol));
    EXPECT_MATRIX_NEAR(a.transformFrom(p), (a.matrix() * p.homogeneous()).head<2>(), kTol);
    EXPECT_MATRIX_NEAR(a.transformTo(p), a.inverse().transformFrom(p), kTol);
    EXPECT_MATRIX_NEAR(a.transformTo(a.transformFrom(p)), p, kTol);
    EXPECT_MATRIX_NEAR((a * b).transformFrom(p), a.transformFrom(b.transformFrom(p)), kTol);
    // Adjoint: T · Exp(ξ) = Exp(Ad ξ) · T, and Ad is a homomorphism.
    const Vector3 xi = random.tangent(random.angle());
    EXPECT_TRUE((a * SE2::Exp(xi)).equals(SE2::Exp(a.adjoint() * xi) * a, kTol));
    EXPECT_MATRIX_NEAR((a * b).adjoint(), a.adjoint() * b.adjoint(), kTol);
    EXPECT_MATRIX_NEAR(a.inverse().adjoint(), a.adjoint().inverse(), kTol);
    checkRetractInvertsLocalCoordinates(a, b, random.tangent(0.5 * random.angle()), kTol);
  }
}

TEST(SE2Test, ExpIsTheExactExponential) {
  Random random;
  std::vector<Vector3> tangents;
  for (double theta : kEdgeAngles) tangents.push_back(random.tangent(theta));
  for (int i = 0; i < kRandomTrials; ++i) tangents.push_back(random.tangent(random.uniform(-6.0, 6.0)));
  for (const Vector3& xi : tangents) {
    EXPECT_MATRIX_NEAR(SE2::Exp(xi).matrix(), expm(hat(xi)), 1e-12) << xi.transpose();
  }
  // Pure translation and pure rotation.
  EXPECT_TRUE(SE2::Exp(Vector3(1.0, 2.0, 0.0)).equals(SE2(1.0, 2.0, 0.0), 0.0));
  EXPECT_TRUE(SE2::Exp(Vector3(0.0, 0.0, 0.7)).equals(SE2(0.0, 0.0, 0.7), 0.0));
  // Unit forward speed for a half turn: a semicircle of radius 1/π ends at (0, 2/π).
  EXPECT_TRUE(SE2::Exp(Vector3(1.0, 0.0, kPi)).equals(SE2(0.0, 2.0 / kPi, kPi), kTol));
}

TEST(SE2Test, ExpLogRoundTrip) {
  Random random;
  std::vector<Vector3> tangents;
  for (double theta : kEdgeAngles) {
    tangents.push_back(random.tangent(theta));
    tangents.push_back(Vector3(0.0, 0.0, theta));
  }
  for (int i = 0; i < kRandomTrials; ++i) tangents.push_back(random.tangent(random.angle()));
  for (const Vector3& xi : tangents) {
    EXPECT_MATRIX_NEAR(SE2::Log(SE2::Exp(xi)), xi, kTol) << xi.transpose();
  }
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE2 T = random.pose();
    EXPECT_TRUE(SE2::Exp(SE2::Log(T)).equals(T, kTol)) << T;
  }
  // At θ = π exactly Log gives +π and still inverts Exp.
  for (const SE2& T : {SE2(SO2::fromCosSin(-1.0, 0.0), Point2(1.0, 2.0)),
                       SE2(SO2::fromCosSin(-1.0, -0.0), Point2(-3.0, 0.5)), SE2(1.0, 2.0, -kPi)}) {
    const Vector3 xi = SE2::Log(T);
    EXPECT_NEAR(xi(2), kPi, kTol);
    EXPECT_TRUE(SE2::Exp(xi).equals(T, kTol)) << T;
  }
}

TEST(SE2Test, RightJacobianMatchesSeries) {
  Random random;
  // Sweep across the angles where the implementation changes between series and closed forms.
  std::vector<double> angles = kRightJacobianSweepAngles;
  for (double theta : kEdgeAngles) angles.push_back(theta);
  for (double theta : angles) {
    for (double sign : {1.0, -1.0}) {
      const Vector3 xi = random.tangent(sign * theta);
      SCOPED_TRACE(::testing::Message() << "xi = " << xi.transpose());
      const Matrix3 series = rightJacobianSeries(ad(xi));
      EXPECT_MATRIX_NEAR(SE2::rightJacobian(xi), series, 1e-14);
      EXPECT_MATRIX_NEAR(SE2::rightJacobianInverse(xi), series.inverse(), 1e-14);
    }
  }
}

TEST(SE2Test, JacobiansOnRandomInputs) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE2 a = random.pose(), b = random.pose();
    checkJacobians(a, b, random.point());
    checkExpJacobians(random.tangent(random.angle()));
    checkExpJacobians(random.tangent(random.uniform(-6.0, 6.0)));  // Exp and Jr are fine beyond ±π
  }
}

TEST(SE2Test, JacobiansAtEdgeAngles) {
  Random random;
  for (double ta : kEdgeAngles) {
    for (double tb : {0.0, 1e-6, kPi - 1e-6, -kPi + 1e-3, 1.0}) {
      checkJacobians(SE2(SO2(ta), random.point()), SE2(SO2(tb), random.point()), random.point());
    }
    checkExpJacobians(random.tangent(ta));
    checkExpJacobians(Vector3(0.0, 0.0, ta));
  }
  // Log Jacobian at the identity and for pure translations.
  checkJacobians(SE2(), SE2(), Point2::Zero());
  checkJacobians(SE2(3.0, -1.0, 0.0), SE2(0.0, 2.0, 0.0), Point2(1.0, 1.0));
}

TEST(SE2Test, Interpolate) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE2 a = random.pose(), b = random.pose();
    EXPECT_TRUE(a.interpolate(b, 0.0).equals(a, kTol));
    EXPECT_TRUE(a.interpolate(b, 1.0).equals(b, 1e-12));
    const SE2 mid = a.interpolate(b, 0.5);
    EXPECT_TRUE(a.between(mid).equals(mid.between(b), 1e-12));
    EXPECT_MATRIX_NEAR(SE2::Log(a.between(mid)), 0.5 * SE2::Log(a.between(b)), 1e-12);
  }
  // Constant twist: halfway along a quarter turn of radius 1 about (0, 1), not halfway along the chord.
  const SE2 a(0.0, 0.0, 0.0), b(1.0, 1.0, kPi / 2);
  const SE2 mid = a.interpolate(b, 0.5);
  EXPECT_TRUE(mid.equals(SE2(std::sin(kPi / 4), 1.0 - std::cos(kPi / 4), kPi / 4), kTol)) << mid;
}

}  // namespace
}  // namespace semslam
