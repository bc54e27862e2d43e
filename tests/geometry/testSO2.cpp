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
#include "support/NumericalDerivative.h"

namespace semslam {
namespace {

constexpr double kPi = std::numbers::pi;
// Central differences with h = 1e-6: truncation ~1e-12, rounding ~1e-10 relative, so 1e-7 is tight but safe.
constexpr double kJacobianTol = 1e-7;
constexpr double kTol = 1e-13;
constexpr int kRandomTrials = 50;

::testing::AssertionResult MatricesNear(const char* actualExpr, const char* expectedExpr, const char*,
                                        const Matrix& actual, const Matrix& expected, double tol) {
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols()) {
    return ::testing::AssertionFailure() << actualExpr << " is " << actual.rows() << "x" << actual.cols() << ", "
                                         << expectedExpr << " is " << expected.rows() << "x" << expected.cols();
  }
  const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
  const double error = (actual - expected).cwiseAbs().maxCoeff();
  if (error <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actualExpr << " differs from " << expectedExpr << " by " << error
                                       << " > " << tol << " * " << scale << "\n"
                                       << actualExpr << " =\n"
                                       << actual << "\n"
                                       << expectedExpr << " =\n"
                                       << expected;
}
#define EXPECT_MATRIX_NEAR(actual, expected, tol) EXPECT_PRED_FORMAT3(MatricesNear, actual, expected, tol)

template <class Out, class In, class F>
Matrix numeric(F f, const In& x, double h = 1e-6) {
  return test::numericalDerivative<Out, In>(std::function<Out(const In&)>(f), x, h);
}

// Angles at which the formulas switch branches or lose digits if done naively.
const std::vector<double> kEdgeAngles = {0.0,       1e-10,          -1e-10,         1e-6,
                                         -1e-6,     1e-3,           -1e-3,          0.5,
                                         kPi - 1e-3, kPi - 1e-6,   -kPi + 1e-3,    -kPi + 1e-6,
                                         kPi,       -kPi + 1e-12};

struct Random {
  std::mt19937 rng{20240611u};
  double angle() { return std::uniform_real_distribution<double>(-kPi, kPi)(rng); }
  Point2 point() {
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    const double x = u(rng);
    return Point2(x, u(rng));
  }
};

// A finite-difference step that keeps Log(x ⊕ ±h e_i) on the same side of its branch cut at ±π.
double logStep(double theta) { return std::min(1e-6, 0.1 * (kPi - std::abs(theta))); }

void checkJacobians(const SO2& a, const SO2& b, const Point2& p) {
  SCOPED_TRACE(::testing::Message() << "a = " << a << ", b = " << b << ", p = " << p.transpose());
  Matrix1 H1, H2, H;
  a.compose(b, &H1, &H2);
  EXPECT_MATRIX_NEAR(H1, numeric<SO2>([&](const SO2& x) { return x.compose(b); }, a), kJacobianTol);
  EXPECT_MATRIX_NEAR(H2, numeric<SO2>([&](const SO2& x) { return a.compose(x); }, b), kJacobianTol);

  a.inverse(&H);
  EXPECT_MATRIX_NEAR(H, numeric<SO2>([](const SO2& x) { return x.inverse(); }, a), kJacobianTol);

  a.between(b, &H1, &H2);
  EXPECT_MATRIX_NEAR(H1, numeric<SO2>([&](const SO2& x) { return x.between(b); }, a), kJacobianTol);
  EXPECT_MATRIX_NEAR(H2, numeric<SO2>([&](const SO2& x) { return a.between(x); }, b), kJacobianTol);

  MatrixN<2, 1> Hr;
  Matrix2 Hp;
  a.rotate(p, &Hr, &Hp);
  EXPECT_MATRIX_NEAR(Hr, numeric<Point2>([&](const SO2& x) { return x.rotate(p); }, a), kJacobianTol);
  EXPECT_MATRIX_NEAR(Hp, numeric<Point2>([&](const Point2& x) { return a.rotate(x); }, p), kJacobianTol);
  a.unrotate(p, &Hr, &Hp);
  EXPECT_MATRIX_NEAR(Hr, numeric<Point2>([&](const SO2& x) { return x.unrotate(p); }, a), kJacobianTol);
  EXPECT_MATRIX_NEAR(Hp, numeric<Point2>([&](const Point2& x) { return a.unrotate(x); }, p), kJacobianTol);

  const Vector1 xi(a.theta());
  SO2::Exp(xi, &H);
  EXPECT_MATRIX_NEAR(H, numeric<SO2>([](const Vector1& v) { return SO2::Exp(v); }, xi), kJacobianTol);

  if (kPi - std::abs(a.theta()) > 1e-7) {  // Log jumps at ±π; closer than this no finite step is usable
    SO2::Log(a, &H);
    EXPECT_MATRIX_NEAR(H, numeric<Vector1>([](const SO2& x) { return SO2::Log(x); }, a, logStep(a.theta())),
                       kJacobianTol);
  }
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
  std::vector<double> angles = kEdgeAngles;
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
    EXPECT_MATRIX_NEAR((a * b).matrix(), a.matrix() * b.matrix(), kTol);
    EXPECT_MATRIX_NEAR(a.compose(b).matrix(), (a * b).matrix(), 0.0);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().transpose(), kTol);
    EXPECT_TRUE((a * a.inverse()).equals(SO2(), kTol));
    EXPECT_TRUE(a.between(b).equals(a.inverse() * b, kTol));
    EXPECT_TRUE(((a * b) * c).equals(a * (b * c), kTol));
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
  for (double ta : kEdgeAngles) {
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
