// Tests of SO3: hat/vee, Exp against Eigen and a matrix exponential, Log accuracy near 0 and near π, quaternion
// and axis-angle conversions, the right Jacobian and its inverse (against the series Σ (-ω^)^k/(k+1)!), and every
// analytic Jacobian against central differences (tests/support/NumericalDerivative.h) on seeded random inputs and
// on edge-case angles.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "semslam/geometry/SO3.h"
#include "support/LieGroupTesting.h"
#include "support/MatrixExponential.h"
#include "support/RandomGeometry.h"

namespace semslam {
namespace {

using namespace test;  // kPi, kTol, kRandomTrials, kEdgeAngles, the Jacobian checks, EXPECT_MATRIX_NEAR

struct Random : RandomSpace {
  Random() : RandomSpace(20240613u) {}
};

void checkJacobians(const SO3& a, const SO3& b, const Point3& p) {
  SCOPED_TRACE(::testing::Message() << "a = " << a << ", b = " << b << ", p = " << p.transpose());
  checkGroupOperationJacobians(a, b);
  checkActionJacobians(a, p, &SO3::rotate);
  checkActionJacobians(a, p, &SO3::unrotate);
  checkLogJacobian(a, SO3::Log(a).norm());
}

void checkExpJacobians(const Vector3& omega) { checkExpAndRightJacobians<SO3>(omega, 1e-15); }

// ω = angle · axis for each edge angle, about random and about coordinate axes.
std::vector<Vector3> edgeTangents(Random& random) {
  std::vector<Vector3> tangents;
  for (double angle : kEdgeAngles) {
    tangents.push_back(angle * random.axis());
    tangents.push_back(angle * Vector3::UnitX());
    tangents.push_back(angle * Vector3(1.0, -1.0, 1.0).normalized());
  }
  return tangents;
}

TEST(SO3Test, HatVee) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const Vector3 w = random.gaussian3(), v = random.gaussian3();
    EXPECT_MATRIX_NEAR(SO3::hat(w) * v, w.cross(v), kTol);
    EXPECT_MATRIX_NEAR(SO3::hat(w).transpose(), -SO3::hat(w), 0.0);
    EXPECT_MATRIX_NEAR(SO3::vee(SO3::hat(w)), w, 0.0);
  }
  EXPECT_EQ(SO3::kDim, 3);
  EXPECT_MATRIX_NEAR(SO3().matrix(), Matrix3::Identity(), 0.0);
}

TEST(SO3Test, ExpMatchesRodriguesReferences) {
  Random random;
  std::vector<Vector3> tangents = edgeTangents(random);
  for (int i = 0; i < kRandomTrials; ++i) tangents.push_back(random.uniform(0.0, 7.0) * random.axis());
  for (const Vector3& w : tangents) {
    SCOPED_TRACE(::testing::Message() << "omega = " << w.transpose());
    const Matrix3 R = SO3::Exp(w).matrix();
    EXPECT_MATRIX_NEAR(R, expm(SO3::hat(w)), 1e-13);
    const double theta = w.norm();
    if (theta > 0.0) {
      EXPECT_MATRIX_NEAR(R, Eigen::AngleAxisd(theta, w / theta).toRotationMatrix(), 1e-15);
    }
    EXPECT_MATRIX_NEAR(R * R.transpose(), Matrix3::Identity(), 1e-15);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
  }
  // Large angles wrap.
  const Vector3 axis = random.axis();
  EXPECT_TRUE(SO3::Exp((0.3 + 20 * kPi) * axis).equals(SO3::Exp(0.3 * axis), 1e-13));
}

TEST(SO3Test, LogInvertsExp) {
  Random random;
  std::vector<Vector3> tangents = edgeTangents(random);
  for (int i = 0; i < kRandomTrials; ++i) tangents.push_back(random.uniform(0.0, kPi) * random.axis());
  for (const Vector3& w : tangents) {
    EXPECT_MATRIX_NEAR(SO3::Log(SO3::Exp(w)), w, kTol) << w.transpose();
  }
  for (int i = 0; i < kRandomTrials; ++i) {
    const SO3 R = random.rotation();
    const Vector3 w = SO3::Log(R);
    EXPECT_LE(w.norm(), kPi);
    EXPECT_TRUE(SO3::Exp(w).equals(R, kTol)) << R;
    const Eigen::AngleAxisd reference(R.matrix());
    EXPECT_MATRIX_NEAR(w, reference.angle() * reference.axis(), 1e-12);
  }
}

TEST(SO3Test, LogIsAccurateNearPi) {
  // acos((tr R - 1)/2) loses about half the digits here; the symmetric-part branch must not.
  Random random;
  for (double gap : {1e-3, 1e-5, 1e-6, 1e-8, 1e-10, 1e-12}) {
    for (int i = 0; i < 10; ++i) {
      const Vector3 w = (kPi - gap) * random.axis();
      EXPECT_MATRIX_NEAR(SO3::Log(SO3::Exp(w)), w, 1e-14) << "gap " << gap;
    }
  }
  // Exactly π: either axis sign is right, but the result must reproduce R.
  std::vector<Vector3> axes = {Vector3::UnitX(), Vector3::UnitY(), Vector3::UnitZ(), Vector3(1, 1, 0).normalized(),
                               Vector3(-1, 2, 3).normalized()};
  for (int i = 0; i < 10; ++i) axes.push_back(random.axis());
  for (const Vector3& axis : axes) {
    const SO3 R = SO3::Exp(kPi * axis);
    const Vector3 w = SO3::Log(R);
    EXPECT_NEAR(w.norm(), kPi, kTol) << axis.transpose();
    EXPECT_NEAR(std::abs(w.normalized().dot(axis)), 1.0, kTol) << axis.transpose();
    EXPECT_TRUE(SO3::Exp(w).equals(R, 1e-15)) << axis.transpose();
  }
  Matrix3 flipYZ = Matrix3::Identity();
  flipYZ(1, 1) = flipYZ(2, 2) = -1.0;
  EXPECT_MATRIX_NEAR(SO3::Log(SO3(flipYZ)).cwiseAbs(), Vector3(kPi, 0.0, 0.0), kTol);
}

TEST(SO3Test, RightJacobianMatchesSeries) {
  Random random;
  // Sweep across the angles where the implementation changes between series and closed forms.
  std::vector<double> angles = kRightJacobianSweepAngles;
  for (double angle : angles) {
    const Vector3 w = angle * random.axis();
    SCOPED_TRACE(::testing::Message() << "omega = " << w.transpose());
    const Matrix3 series = rightJacobianSeries(SO3::hat(w));
    EXPECT_MATRIX_NEAR(SO3::rightJacobian(w), series, 1e-15);
    EXPECT_MATRIX_NEAR(SO3::rightJacobianInverse(w), series.inverse(), 1e-14);
    // Jl(ω) = Jr(-ω) = Jr(ω)ᵀ.
    EXPECT_MATRIX_NEAR(SO3::rightJacobian(-w), SO3::rightJacobian(w).transpose(), 1e-15);
  }
}

TEST(SO3Test, Quaternions) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const Vector3 g = random.gaussian3();
    const double w = random.uniform(-1.0, 1.0);
    const Eigen::Quaterniond q(w, g.x(), g.y(), g.z());  // deliberately not normalised
    const SO3 R = SO3::fromQuaternion(q);
    EXPECT_MATRIX_NEAR(R.matrix(), q.normalized().toRotationMatrix(), kTol);
    EXPECT_TRUE(SO3::fromQuaternion(Eigen::Quaterniond(-q.coeffs())).equals(R, kTol));
    EXPECT_TRUE(SO3::fromQuaternion(Eigen::Quaterniond(3.7 * q.coeffs())).equals(R, kTol));
    const Eigen::Quaterniond back = R.toQuaternion();
    EXPECT_GE(back.w(), 0.0);
    EXPECT_NEAR(back.norm(), 1.0, kTol);
    EXPECT_NEAR(std::abs(back.coeffs().dot(q.normalized().coeffs())), 1.0, kTol);
    EXPECT_TRUE(SO3::fromQuaternion(back).equals(R, kTol));
  }
  // (w, x, y, z) = (cos 45°, 0, 0, sin 45°) is 90° about z.
  const SO3 Rz = SO3::fromQuaternion(Eigen::Quaterniond(std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)));
  EXPECT_MATRIX_NEAR(Rz.rotate(Point3::UnitX()), Point3::UnitY(), kTol);
  EXPECT_THROW(SO3::fromQuaternion(Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0)), std::invalid_argument);
}

TEST(SO3Test, AxisAngleAndNearest) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const Vector3 axis = random.gaussian3();
    const double angle = random.uniform(-4.0, 4.0);
    const SO3 R = SO3::fromAxisAngle(axis, angle);
    EXPECT_MATRIX_NEAR(R.matrix(), Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(), kTol);
    EXPECT_TRUE(SO3::fromAxisAngle(5.0 * axis, angle).equals(R, kTol));
    // nearest() recovers R from a slightly perturbed matrix, and leaves a rotation unchanged.
    Matrix3 noisy = R.matrix();
    for (int k = 0; k < 9; ++k) noisy(k / 3, k % 3) += 1e-9 * random.uniform(-1.0, 1.0);
    const SO3 projected = SO3::nearest(noisy);
    EXPECT_MATRIX_NEAR(projected.matrix() * projected.matrix().transpose(), Matrix3::Identity(), 1e-15);
    EXPECT_NEAR(projected.matrix().determinant(), 1.0, 1e-15);
    EXPECT_TRUE(projected.equals(R, 1e-8));
    EXPECT_TRUE(SO3::nearest(R.matrix()).equals(R, kTol));
  }
  EXPECT_TRUE(SO3::fromAxisAngle(Vector3::UnitZ(), kPi / 2).equals(SO3::Exp(Vector3(0, 0, kPi / 2)), 0.0));
  EXPECT_THROW(SO3::fromAxisAngle(Vector3::Zero(), 1.0), std::invalid_argument);
  // A reflection is mapped to a proper rotation.
  EXPECT_NEAR(SO3::nearest(-Matrix3::Identity()).matrix().determinant(), 1.0, kTol);
}

TEST(SO3Test, GroupIdentities) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SO3 a = random.rotation(), b = random.rotation(), c = random.rotation();
    const Point3 p = random.point();
    checkGroupAxioms(a, b, c, kTol);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().transpose(), 0.0);
    EXPECT_MATRIX_NEAR(a.rotate(p), a.matrix() * p, kTol);
    EXPECT_MATRIX_NEAR(a.unrotate(a.rotate(p)), p, kTol);
    // Adjoint: R · Exp(ω) = Exp(R ω) · R.
    const Vector3 w = random.uniform(0.0, 3.0) * random.axis();
    EXPECT_MATRIX_NEAR(a.adjoint(), a.matrix(), 0.0);
    EXPECT_TRUE((a * SO3::Exp(w)).equals(SO3::Exp(a.adjoint() * w) * a, kTol));
    checkRetractInvertsLocalCoordinates(a, b, Vector3(random.uniform(0.0, 3.0) * random.axis()), kTol);
  }
}

TEST(SO3Test, JacobiansOnRandomInputs) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SO3 a = random.rotation(), b = random.rotation();
    checkJacobians(a, b, random.point());
    checkExpJacobians(random.uniform(0.0, kPi) * random.axis());
    checkExpJacobians(random.uniform(kPi, 6.0) * random.axis());  // Exp and Jr are fine beyond π
  }
}

TEST(SO3Test, JacobiansAtEdgeAngles) {
  Random random;
  const std::vector<Vector3> tangents = edgeTangents(random);
  for (const Vector3& wa : tangents) {
    for (double tb : {0.0, 1e-6, kPi - 1e-6, 1.0}) {
      checkJacobians(SO3::Exp(wa), SO3::Exp(tb * random.axis()), random.point());
    }
    checkExpJacobians(wa);
  }
}

TEST(SO3Test, Interpolate) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SO3 a = random.rotation(), b = random.rotation();
    EXPECT_TRUE(a.interpolate(b, 0.0).equals(a, kTol));
    EXPECT_TRUE(a.interpolate(b, 1.0).equals(b, 1e-12));
    const SO3 mid = a.interpolate(b, 0.5);
    EXPECT_TRUE(a.between(mid).equals(mid.between(b), 1e-12));
    // Same geodesic as quaternion slerp (which also takes the shorter arc).
    for (double t : {0.25, 0.5, 0.8}) {
      const SO3 slerp(a.toQuaternion().slerp(t, b.toQuaternion()).toRotationMatrix());
      EXPECT_TRUE(a.interpolate(b, t).equals(slerp, 1e-12)) << t;
    }
  }
}

TEST(SO3Test, Printing) {
  std::ostringstream os;
  os << SO3::Exp(Vector3(0.25, -0.5, 1.0));
  EXPECT_EQ(os.str(), "SO3(0.25, -0.5, 1)");
}

}  // namespace
}  // namespace semslam
