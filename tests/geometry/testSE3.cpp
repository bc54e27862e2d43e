// Tests of SE3: group identities, the exact exponential (against a matrix exponential), Log near 0 and π, the
// right Jacobian and its inverse (against the series Σ (-ad)^k/(k+1)!), every analytic Jacobian against central
// differences (tests/support/NumericalDerivative.h) on seeded random inputs and on edge-case angles, and SE2 as
// the planar restriction of SE3.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include <Eigen/Dense>

#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"
#include "support/LieGroupTesting.h"
#include "support/MatrixExponential.h"
#include "support/RandomGeometry.h"

namespace semslam {
namespace {

using namespace test;  // kPi, kTol, kRandomTrials, kEdgeAngles, the Jacobian checks, EXPECT_MATRIX_NEAR

struct Random : RandomSpace {
  Random() : RandomSpace(20240614u) {}
  SE3 pose() {
    const SO3 R = rotation();
    return SE3(R, point());
  }
  Vector6 tangent(const Vector3& phi) {
    Vector6 xi;
    xi << point(), phi;
    return xi;
  }
};

Matrix4 hat(const Vector6& xi) {
  Matrix4 X = Matrix4::Zero();
  X.topLeftCorner<3, 3>() = SO3::hat(xi.tail<3>());
  X.topRightCorner<3, 1>() = xi.head<3>();
  return X;
}

// ad(ξ) = [φ^ ρ^; 0 φ^] (translation first), with ad(ξ) η = vee([hat ξ, hat η]).
Matrix6 ad(const Vector6& xi) {
  Matrix6 A = Matrix6::Zero();
  A.topLeftCorner<3, 3>() = SO3::hat(xi.tail<3>());
  A.topRightCorner<3, 3>() = SO3::hat(xi.head<3>());
  A.bottomRightCorner<3, 3>() = SO3::hat(xi.tail<3>());
  return A;
}

void checkJacobians(const SE3& a, const SE3& b, const Point3& p) {
  SCOPED_TRACE(::testing::Message() << "a = " << a << ", b = " << b << ", p = " << p.transpose());
  checkGroupOperationJacobians(a, b);
  checkActionJacobians(a, p, &SE3::transformFrom);
  checkActionJacobians(a, p, &SE3::transformTo);
  checkLogJacobian(a, SO3::Log(a.rotation()).norm());
}

void checkExpJacobians(const Vector6& xi) { checkExpAndRightJacobians<SE3>(xi, 1e-15); }

// ξ = (random ρ, angle · axis) for each edge angle, about random and about coordinate axes, plus ρ = 0.
std::vector<Vector6> edgeTangents(Random& random) {
  std::vector<Vector6> tangents;
  for (double angle : kEdgeAngles) {
    tangents.push_back(random.tangent(angle * random.axis()));
    tangents.push_back(random.tangent(angle * Vector3::UnitZ()));
    Vector6 pure = Vector6::Zero();
    pure.tail<3>() = angle * random.axis();
    tangents.push_back(pure);
  }
  return tangents;
}

TEST(SE3Test, ConstructionAndAccessors) {
  const SO3 R = SO3::Exp(Vector3(0.1, -0.2, 0.3));
  const Point3 t(1.0, -2.0, 3.0);
  const SE3 T(R, t);
  EXPECT_TRUE(T.rotation().equals(R, 0.0));
  EXPECT_MATRIX_NEAR(T.translation(), t, 0.0);
  Matrix4 M = Matrix4::Identity();
  M.topLeftCorner<3, 3>() = R.matrix();
  M.topRightCorner<3, 1>() = t;
  EXPECT_MATRIX_NEAR(T.matrix(), M, 0.0);
  EXPECT_MATRIX_NEAR(SE3().matrix(), Matrix4::Identity(), 0.0);
  EXPECT_EQ(SE3::kDim, 6);
  std::ostringstream os;
  os << SE3(SO3::Exp(Vector3(0.25, 0.0, -0.5)), Point3(1.0, 2.0, -3.0));
  EXPECT_EQ(os.str(), "SE3(t: 1 2 -3, R: 0.25 0 -0.5)");
}

TEST(SE3Test, GroupIdentities) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE3 a = random.pose(), b = random.pose(), c = random.pose();
    const Point3 p = random.point();
    checkGroupAxioms(a, b, c, kTol);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().inverse(), kTol);
    EXPECT_TRUE((a * a.between(b)).equals(b, kTol));
    EXPECT_MATRIX_NEAR(a.transformFrom(p), (a.matrix() * p.homogeneous()).head<3>(), kTol);
    EXPECT_MATRIX_NEAR(a.transformTo(p), a.inverse().transformFrom(p), kTol);
    EXPECT_MATRIX_NEAR(a.transformTo(a.transformFrom(p)), p, kTol);
    // Adjoint: T · Exp(ξ) = Exp(Ad ξ) · T, Ad = [R t^R; 0 R], and Ad is a homomorphism.
    const Vector6 xi = random.tangent(random.uniform(0.0, 3.0) * random.axis());
    EXPECT_TRUE((a * SE3::Exp(xi)).equals(SE3::Exp(a.adjoint() * xi) * a, 1e-12));
    const Matrix6 Ad = a.adjoint();
    Matrix6 expectedAd = Matrix6::Zero();
    expectedAd.topLeftCorner(3, 3) = a.rotation().matrix();
    expectedAd.bottomRightCorner(3, 3) = a.rotation().matrix();
    expectedAd.topRightCorner(3, 3) = SO3::hat(a.translation()) * a.rotation().matrix();
    EXPECT_MATRIX_NEAR(Ad, expectedAd, kTol);
    EXPECT_MATRIX_NEAR((a * b).adjoint(), a.adjoint() * b.adjoint(), kTol);
    EXPECT_MATRIX_NEAR(a.inverse().adjoint(), a.adjoint().inverse(), kTol);
    // Ad(T) ad(ξ) Ad(T)⁻¹ = ad(Ad(T) ξ).
    EXPECT_MATRIX_NEAR(Ad * ad(xi) * Ad.inverse(), ad(Ad * xi), 1e-12);
    checkRetractInvertsLocalCoordinates(a, b, random.tangent(random.uniform(0.0, 3.0) * random.axis()), kTol);
  }
}

TEST(SE3Test, ExpIsTheExactExponential) {
  Random random;
  std::vector<Vector6> tangents = edgeTangents(random);
  for (int i = 0; i < kRandomTrials; ++i) tangents.push_back(random.tangent(random.uniform(0.0, 6.0) * random.axis()));
  for (const Vector6& xi : tangents) {
    EXPECT_MATRIX_NEAR(SE3::Exp(xi).matrix(), expm(hat(xi)), 1e-12) << xi.transpose();
  }
  // Pure translation.
  Vector6 xi = Vector6::Zero();
  xi.head<3>() = Vector3(1.0, -2.0, 3.0);
  EXPECT_TRUE(SE3::Exp(xi).equals(SE3(SO3(), Point3(1.0, -2.0, 3.0)), 0.0));
}

TEST(SE3Test, ExpLogRoundTrip) {
  Random random;
  std::vector<Vector6> tangents = edgeTangents(random);
  for (int i = 0; i < kRandomTrials; ++i) tangents.push_back(random.tangent(random.uniform(0.0, kPi) * random.axis()));
  for (const Vector6& xi : tangents) {
    EXPECT_MATRIX_NEAR(SE3::Log(SE3::Exp(xi)), xi, 1e-13) << xi.transpose();
  }
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE3 T = random.pose();
    EXPECT_TRUE(SE3::Exp(SE3::Log(T)).equals(T, 1e-13)) << T;
  }
  // Near and at π.
  for (double gap : {1e-6, 1e-9, 0.0}) {
    for (int i = 0; i < 5; ++i) {
      const SE3 T(SO3::Exp((kPi - gap) * random.axis()), random.point());
      const Vector6 xi = SE3::Log(T);
      EXPECT_NEAR(xi.tail<3>().norm(), kPi - gap, kTol);
      EXPECT_TRUE(SE3::Exp(xi).equals(T, 1e-13)) << T;
    }
  }
}

TEST(SE3Test, RightJacobianMatchesSeries) {
  Random random;
  // Sweep across the angles where the implementation changes between series and closed forms.
  std::vector<double> angles = kRightJacobianSweepAngles;
  for (double angle : angles) {
    const Vector6 xi = random.tangent(angle * random.axis());
    SCOPED_TRACE(::testing::Message() << "xi = " << xi.transpose());
    const Matrix6 series = rightJacobianSeries(ad(xi));
    EXPECT_MATRIX_NEAR(SE3::rightJacobian(xi), series, 1e-14);
    EXPECT_MATRIX_NEAR(SE3::rightJacobianInverse(xi), series.inverse(), 1e-13);
    // Jl(ξ) = Jr(-ξ), and Jr(ξ) = Ad(Exp(-ξ)) Jl(ξ).
    EXPECT_MATRIX_NEAR(SE3::rightJacobian(xi), SE3::Exp(-xi).adjoint() * SE3::rightJacobian(-xi), 1e-13);
  }
}

TEST(SE3Test, JacobiansOnRandomInputs) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE3 a = random.pose(), b = random.pose();
    checkJacobians(a, b, random.point());
    checkExpJacobians(random.tangent(random.uniform(0.0, kPi) * random.axis()));
    checkExpJacobians(random.tangent(random.uniform(kPi, 6.0) * random.axis()));  // fine beyond π
  }
}

TEST(SE3Test, JacobiansAtEdgeAngles) {
  Random random;
  for (const Vector6& xa : edgeTangents(random)) {
    for (double tb : {0.0, 1e-6, kPi - 1e-6, 1.0}) {
      checkJacobians(SE3::Exp(xa), SE3(SO3::Exp(tb * random.axis()), random.point()), random.point());
    }
    checkExpJacobians(xa);
  }
  checkJacobians(SE3(), SE3(), Point3::Zero());
}

TEST(SE3Test, Interpolate) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SE3 a = random.pose(), b = random.pose();
    EXPECT_TRUE(a.interpolate(b, 0.0).equals(a, kTol));
    EXPECT_TRUE(a.interpolate(b, 1.0).equals(b, 1e-12));
    const SE3 mid = a.interpolate(b, 0.5);
    EXPECT_TRUE(a.between(mid).equals(mid.between(b), 1e-12));
    EXPECT_MATRIX_NEAR(SE3::Log(a.between(mid)), 0.5 * SE3::Log(a.between(b)), 1e-12);
    // The rotation follows slerp.
    EXPECT_TRUE(mid.rotation().equals(a.rotation().interpolate(b.rotation(), 0.5), 1e-12));
  }
}

// ---- SE2 is the planar restriction of SE3 ----------------------------------------------------------------------

SE3 embed(const SE2& T) {
  return SE3(SO3::fromAxisAngle(Vector3::UnitZ(), T.theta()), Point3(T.x(), T.y(), 0.0));
}
// SE2 tangent (x, y, θ) sits at indices (0, 1, 5) of the SE3 tangent (ρ, φ).
constexpr std::array<int, 3> kPlanar = {0, 1, 5};
Vector6 embed(const Vector3& xi) {
  Vector6 v = Vector6::Zero();
  for (int i = 0; i < 3; ++i) v(kPlanar[i]) = xi(i);
  return v;
}
Matrix3 planarBlock(const Matrix6& M) {
  Matrix3 B;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) B(i, j) = M(kPlanar[i], kPlanar[j]);
  return B;
}

TEST(SE3Test, SE2IsThePlanarRestriction) {
  Random random;
  std::vector<double> angles = kEdgeAngles;
  for (int i = 0; i < kRandomTrials; ++i) angles.push_back(random.uniform(-kPi, kPi));
  for (double angle : angles) {
    const Point3 ta = random.point(), tb = random.point(), p3 = random.point();
    const SE2 a(ta.x(), ta.y(), angle), b(tb.x(), tb.y(), random.uniform(-kPi, kPi));
    const SE3 A = embed(a), B = embed(b);
    const Point2 p = p3.head<2>();
    SCOPED_TRACE(::testing::Message() << "a = " << a << ", b = " << b);

    Matrix3 h1, h2;
    Matrix6 H1, H2;
    EXPECT_TRUE(embed(a.compose(b, &h1, &h2)).equals(A.compose(B, &H1, &H2), kTol));
    EXPECT_MATRIX_NEAR(h1, planarBlock(H1), kTol);
    EXPECT_MATRIX_NEAR(h2, planarBlock(H2), kTol);
    EXPECT_TRUE(embed(a.between(b, &h1, &h2)).equals(A.between(B, &H1, &H2), kTol));
    EXPECT_MATRIX_NEAR(h1, planarBlock(H1), kTol);
    EXPECT_MATRIX_NEAR(h2, planarBlock(H2), kTol);
    EXPECT_TRUE(embed(a.inverse(&h1)).equals(A.inverse(&H1), kTol));
    EXPECT_MATRIX_NEAR(h1, planarBlock(H1), kTol);
    EXPECT_MATRIX_NEAR(a.adjoint(), planarBlock(A.adjoint()), kTol);

    Matrix23 hpose;
    Matrix36 Hpose;
    const Point3 pz(p.x(), p.y(), 0.0);
    EXPECT_MATRIX_NEAR(a.transformFrom(p, &hpose), A.transformFrom(pz, &Hpose).head<2>(), kTol);
    for (int j = 0; j < 3; ++j) EXPECT_MATRIX_NEAR(hpose.col(j), Hpose.col(kPlanar[j]).head<2>(), kTol);
    EXPECT_MATRIX_NEAR(a.transformTo(p, &hpose), A.transformTo(pz, &Hpose).head<2>(), kTol);
    for (int j = 0; j < 3; ++j) EXPECT_MATRIX_NEAR(hpose.col(j), Hpose.col(kPlanar[j]).head<2>(), kTol);

    const Vector3 xi(ta.x(), ta.y(), angle);
    EXPECT_TRUE(embed(SE2::Exp(xi, &h1)).equals(SE3::Exp(embed(xi), &H1), kTol));
    EXPECT_MATRIX_NEAR(h1, planarBlock(H1), kTol);
    EXPECT_MATRIX_NEAR(SE2::rightJacobian(xi), planarBlock(SE3::rightJacobian(embed(xi))), kTol);
    EXPECT_MATRIX_NEAR(SE2::rightJacobianInverse(xi), planarBlock(SE3::rightJacobianInverse(embed(xi))), 1e-12);
    EXPECT_MATRIX_NEAR(embed(SE2::Log(a, &h1)), SE3::Log(A, &H1), 1e-12);
    EXPECT_MATRIX_NEAR(h1, planarBlock(H1), 1e-12);
  }
}

}  // namespace
}  // namespace semslam
