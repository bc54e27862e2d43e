// Tests of SO2: group identities, the (-π, π] range of Log, and every analytic Jacobian against central
// differences (tests/support/NumericalDerivative.h) on seeded random inputs and on edge-case angles.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "semslam/geometry/SO2.h"
#include "support/LieGroupTesting.h"
#include "support/RandomGeometry.h"

namespace semslam {
namespace {

using namespace test;  // kPi, kTol, kRandomTrials, kEdgeAngles, the Jacobian checks, EXPECT_MATRIX_NEAR

// The shared edge angles, plus π itself and the angle just above −π: SO2's Log range is (−π, π].
const std::vector<double> kSO2EdgeAngles = [] {
  std::vector<double> angles = kEdgeAngles;
  angles.push_back(kPi);
  angles.push_back(-kPi + 1e-12);
  return angles;
}();

struct Random : RandomPlane {
  Random() : RandomPlane(20240611u) {}
};

void checkJacobians(const SO2& a, const SO2& b, const Point2& p) {
  SCOPED_TRACE(::testing::Message() << "a = " << a << ", b = " << b << ", p = " << p.transpose());
  checkGroupOperationJacobians(a, b);
  checkActionJacobians(a, p, &SO2::rotate);
  checkActionJacobians(a, p, &SO2::unrotate);
  checkExpJacobian<SO2>(Vector1(a.theta()));
  checkLogJacobian(a, a.theta());
}

TEST(SO2Test, ConstructionAndAccessors) {
  const SO2 R(0.3);
  EXPECT_DOUBLE_EQ(R.theta(), 0.3);
  EXPECT_DOUBLE_EQ(R.c(), std::cos(0.3));
  EXPECT_DOUBLE_EQ(R.s(), std::sin(0.3));
  Matrix2 M;
  M << std::cos(0.3), -std::sin(0.3), std::sin(0.3), std::cos(0.3);
  EXPECT_MATRIX_NEAR(R.matrix(), M, kTol);
  EXPECT_MATRIX_NEAR(SO2().matrix(), Matrix2::Identity(), 0.0);
  EXPECT_EQ(SO2::kDim, 1);
}

TEST(SO2Test, FromCosSinNormalises) {
  const SO2 R = SO2::fromCosSin(3.0, 4.0);
  EXPECT_NEAR(R.c(), 0.6, kTol);
  EXPECT_NEAR(R.s(), 0.8, kTol);
  EXPECT_NEAR(R.theta(), std::atan2(4.0, 3.0), kTol);
  const SO2 tiny = SO2::fromCosSin(1e-200, -1e-200);
  EXPECT_NEAR(tiny.theta(), -kPi / 4, kTol);
  EXPECT_THROW(SO2::fromCosSin(0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(SO2::fromCosSin(std::numeric_limits<double>::quiet_NaN(), 1.0), std::invalid_argument);
  EXPECT_THROW(SO2::fromCosSin(std::numeric_limits<double>::infinity(), 1.0), std::invalid_argument);
}

TEST(SO2Test, LogRangeIsHalfOpenAtMinusPi) {
  // (-1, ±0) is the rotation by π, and Log must give +π for both signs of zero.
  EXPECT_EQ(SO2::fromCosSin(-1.0, 0.0).theta(), kPi);
  EXPECT_EQ(SO2::fromCosSin(-1.0, -0.0).theta(), kPi);
  EXPECT_EQ(SO2::Log(SO2::fromCosSin(-1.0, -0.0))(0), kPi);
  EXPECT_NEAR(SO2(-kPi).theta(), kPi, kTol);
  EXPECT_NEAR(SO2(3 * kPi).theta(), kPi, 1e-12);
  EXPECT_NEAR(SO2(-kPi + 1e-9).theta(), -kPi + 1e-9, kTol);
  for (double theta = -20.0; theta <= 20.0; theta += 0.01) {
    const double log = SO2::Log(SO2(theta))(0);
    EXPECT_GT(log, -kPi);
    EXPECT_LE(log, kPi);
    const double wrapped = std::remainder(theta, 2 * kPi);
    EXPECT_NEAR(std::remainder(log - wrapped, 2 * kPi), 0.0, 1e-13 * std::max(1.0, std::abs(theta))) << theta;
  }
}

TEST(SO2Test, ExpLogRoundTrip) {
  Random random;
  std::vector<double> angles = kSO2EdgeAngles;
  for (int i = 0; i < kRandomTrials; ++i) angles.push_back(random.angle());
  for (double theta : angles) {
    if (theta == -kPi) continue;
    const Vector1 xi(theta);
    EXPECT_NEAR(SO2::Log(SO2::Exp(xi))(0), theta, kTol) << theta;
    const SO2 R(theta);
    EXPECT_TRUE(SO2::Exp(SO2::Log(R)).equals(R, kTol)) << theta;
  }
}

TEST(SO2Test, GroupIdentities) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SO2 a(random.angle()), b(random.angle()), c(random.angle());
    const Point2 p = random.point();
    checkGroupAxioms(a, b, c, kTol);
    EXPECT_MATRIX_NEAR(a.compose(b).matrix(), (a * b).matrix(), 0.0);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().transpose(), kTol);
    EXPECT_MATRIX_NEAR(a.rotate(p), a.matrix() * p, kTol);
    EXPECT_MATRIX_NEAR(a.unrotate(p), a.matrix().transpose() * p, kTol);
    EXPECT_MATRIX_NEAR(a.unrotate(a.rotate(p)), p, kTol);
    EXPECT_TRUE(a.retract(a.localCoordinates(b)).equals(b, kTol));
    const Vector1 d(0.5 * random.angle());
    EXPECT_NEAR(a.localCoordinates(a.retract(d))(0), d(0), kTol);
    // Adjoint: R · Exp(ξ) = Exp(Ad ξ) · R.
    EXPECT_TRUE((a * SO2::Exp(d)).equals(SO2::Exp(a.adjoint() * d) * a, kTol));
  }
}

TEST(SO2Test, JacobiansOnRandomInputs) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SO2 a(random.angle()), b(random.angle());
    checkJacobians(a, b, random.point());
  }
}

TEST(SO2Test, JacobiansAtEdgeAngles) {
  Random random;
  for (double ta : kSO2EdgeAngles) {
    for (double tb : {0.0, 1e-6, kPi - 1e-6, -kPi + 1e-3, 1.0}) {
      checkJacobians(SO2(ta), SO2(tb), random.point());
    }
  }
}

TEST(SO2Test, Interpolate) {
  Random random;
  for (int i = 0; i < kRandomTrials; ++i) {
    const SO2 a(random.angle()), b(random.angle());
    EXPECT_TRUE(a.interpolate(b, 0.0).equals(a, kTol));
    EXPECT_TRUE(a.interpolate(b, 1.0).equals(b, kTol));
    const SO2 mid = a.interpolate(b, 0.5);
    EXPECT_TRUE(a.between(mid).equals(mid.between(b), kTol));
    EXPECT_LE(std::abs(a.between(mid).theta()), kPi / 2 + kTol);
  }
  // The shortest arc crosses ±π: from +170° to -170° the midpoint is 180°, not 0°.
  const double deg = kPi / 180.0;
  EXPECT_TRUE(SO2(170 * deg).interpolate(SO2(-170 * deg), 0.5).equals(SO2(kPi), kTol));
  EXPECT_TRUE(SO2(170 * deg).interpolate(SO2(-170 * deg), 0.25).equals(SO2(175 * deg), kTol));
  EXPECT_TRUE(SO2(0.1).interpolate(SO2(0.5), 2.0).equals(SO2(0.9), kTol));  // extrapolation
}

TEST(SO2Test, Printing) {
  std::ostringstream os;
  os << SO2(0.25);
  EXPECT_EQ(os.str(), "SO2(0.25)");
}

}  // namespace
}  // namespace semslam
