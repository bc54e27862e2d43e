// Motion models: odometry composition (covariance against Monte Carlo, including a check that wrong conventions
// fail the same test), unicycle integration (pose and input Jacobian against a fine-step RK4 integration of the
// unicycle ODE; covariance against Monte Carlo; the floor), and SE3 velocity integration (against RK4 on
// Ṙ = R ω^, ṫ = R v; Jacobian against central differences).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "semslam/models/OdometryComposition.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/UnicycleModel.h"
#include "semslam/models/VelocityModel3.h"
#include "support/NumericalDerivative.h"
#include "models/ModelsTesting.h"

namespace semslam {
namespace {

using test::matricesNear;

// ---- Monte Carlo helpers ----------------------------------------------------------------------------------------

struct MonteCarlo {
  Matrix covariance;
  Matrix standardError;  // of each covariance entry, for Gaussian samples: sqrt((S_ii S_jj + S_ij²) / N)
};

MonteCarlo sampleCovariance(const std::vector<Vector>& samples) {
  const auto n = static_cast<double>(samples.size());
  const Eigen::Index d = samples.front().size();
  Vector mean = Vector::Zero(d);
  for (const Vector& s : samples) mean += s;
  mean /= n;
  Matrix S = Matrix::Zero(d, d);
  for (const Vector& s : samples) S += (s - mean) * (s - mean).transpose();
  S /= (n - 1.0);
  Matrix se(d, d);
  for (Eigen::Index i = 0; i < d; ++i) {
    for (Eigen::Index j = 0; j < d; ++j) se(i, j) = std::sqrt((S(i, i) * S(j, j) + S(i, j) * S(i, j)) / n);
  }
  return {S, se};
}

/// The largest |predicted − MC| in units of the MC standard error.
double worstDeviation(const Matrix& predicted, const MonteCarlo& mc) {
  return ((predicted - mc.covariance).cwiseAbs().array() / mc.standardError.array()).maxCoeff();
}

Matrix randomCovariance(int d, double sigma, std::mt19937& rng) {
  Matrix A(d, d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) A(i, j) = sigma * standardNormal(rng);
  return A * A.transpose() / d + sigma * sigma * 0.2 * Matrix::Identity(d, d);
}

// ---- composition --------------------------------------------------------------------------------------------------

template <class Group>
void checkCompositionAgainstMonteCarlo(const Group& a, const Group& b, std::mt19937& rng) {
  constexpr int d = Group::kDim;
  const Matrix covA = randomCovariance(d, 0.03, rng);
  const Matrix covB = randomCovariance(d, 0.03, rng);
  const Odometry composed = composeOdometry(Odometry{a, covA}, Odometry{b, covB});
  const Group& c = std::get<Group>(composed.increment);
  ASSERT_TRUE(c.equals(a * b, 1e-12));

  constexpr int kSamples = 200000;
  std::vector<Vector> errors;
  errors.reserve(kSamples);
  const Vector zero = Vector::Zero(d);
  for (int s = 0; s < kSamples; ++s) {
    const VectorN<d> da = sampleGaussian(zero, covA, rng);
    const VectorN<d> db = sampleGaussian(zero, covB, rng);
    const Group sample = a.retract(da) * b.retract(db);
    errors.push_back(c.localCoordinates(sample));
  }
  const MonteCarlo mc = sampleCovariance(errors);
  // 5 standard errors plus the O(σ⁴) terms the first-order formula leaves out (σ² ≈ 1e-3 relative).
  const double scale = composed.covariance.cwiseAbs().maxCoeff();
  const Matrix tolerance = 5.0 * mc.standardError + Matrix::Constant(d, d, 3e-3 * scale);
  EXPECT_TRUE(((composed.covariance - mc.covariance).cwiseAbs().array() <= tolerance.array()).all())
      << "first-order covariance:\n"
      << composed.covariance << "\nMonte Carlo:\n"
      << mc.covariance << "\nstandard errors:\n"
      << mc.standardError;

  // The test can fail: the wrong conventions (no transport, or transport by Ad(a) / Ad(b)) are far outside it.
  Eigen::Matrix<double, d, d> adB = b.inverse().adjoint();
  EXPECT_GT(worstDeviation(covA + covB, mc), 20.0);
  EXPECT_GT(worstDeviation(b.adjoint() * covA * b.adjoint().transpose() + covB, mc), 20.0);
  EXPECT_LT(worstDeviation(adB * covA * adB.transpose() + covB, mc), 8.0);
}

TEST(OdometryComposition, SE2CovarianceMatchesMonteCarlo) {
  std::mt19937 rng(11);
  checkCompositionAgainstMonteCarlo(SE2(1.0, 0.3, 0.4), SE2(2.0, -1.0, 1.2), rng);
}

TEST(OdometryComposition, SE3CovarianceMatchesMonteCarlo) {
  std::mt19937 rng(12);
  const SE3 a(SO3::fromAxisAngle(Vector3(0.2, -0.5, 1.0), 0.7), Point3(1.0, 0.5, -0.2));
  const SE3 b(SO3::fromAxisAngle(Vector3(1.0, 0.3, -0.4), 1.1), Point3(2.0, -1.0, 0.8));
  checkCompositionAgainstMonteCarlo(a, b, rng);
}

TEST(OdometryComposition, IdentityIsNeutralAndCompositionIsAssociative) {
  std::mt19937 rng(3);
  const Odometry a{SE2(1.0, 0.2, 0.3), randomCovariance(3, 0.1, rng)};
  const Odometry b{SE2(0.5, -0.4, -0.8), randomCovariance(3, 0.1, rng)};
  const Odometry c{SE2(-0.3, 0.9, 2.0), randomCovariance(3, 0.1, rng)};
  const Odometry left = composeOdometry(identityOdometry(2), a);
  const Odometry right = composeOdometry(a, identityOdometry(2));
  EXPECT_TRUE(std::get<SE2>(left.increment).equals(std::get<SE2>(a.increment), 1e-15));
  EXPECT_TRUE(matricesNear(left.covariance, a.covariance, 1e-15));
  EXPECT_TRUE(matricesNear(right.covariance, a.covariance, 1e-15));
  // Ad is a homomorphism, so the first-order covariance is exactly associative.
  const Odometry ab_c = composeOdometry(composeOdometry(a, b), c);
  const Odometry a_bc = composeOdometry(a, composeOdometry(b, c));
  EXPECT_TRUE(std::get<SE2>(ab_c.increment).equals(std::get<SE2>(a_bc.increment), 1e-12));
  EXPECT_TRUE(matricesNear(ab_c.covariance, a_bc.covariance, 1e-12));
  // A pure translation b transports Σ_a by Ad(b⁻¹): the heading variance moves into the lateral position.
  const Odometry heading{SE2(), Matrix(Vector3(0.0, 0.0, 0.01).asDiagonal())};
  const Odometry forward{SE2(2.0, 0.0, 0.0), Matrix::Zero(3, 3)};
  const Matrix expected = (Matrix(3, 3) << 0, 0, 0, 0, 0.04, 0.02, 0, 0.02, 0.01).finished();
  EXPECT_TRUE(matricesNear(composeOdometry(heading, forward).covariance, expected, 1e-15));
}

TEST(OdometryComposition, RejectsMismatchedInputs) {
  const Odometry planar = identityOdometry(2);
  const Odometry spatial = identityOdometry(3);
  EXPECT_THROW(composeOdometry(planar, spatial), std::invalid_argument);
  EXPECT_THROW(composeOdometry(Odometry{SE2(), Matrix::Zero(6, 6)}, planar), std::invalid_argument);
  Matrix asymmetric = Matrix::Identity(3, 3);
  asymmetric(0, 1) = 0.5;
  EXPECT_THROW(composeOdometry(Odometry{SE2(), asymmetric}, planar), std::invalid_argument);
  Matrix nan = Matrix::Identity(3, 3);
  nan(2, 2) = std::nan("");
  EXPECT_THROW(composeOdometry(planar, Odometry{SE2(), nan}), std::invalid_argument);
  EXPECT_THROW(identityOdometry(4), std::invalid_argument);
}

// ---- unicycle -----------------------------------------------------------------------------------------------------

/// RK4 on ẋ = v cos θ, ẏ = v sin θ, θ̇ = ω from the identity.
SE2 integrateUnicycleRk4(double v, double omega, double dt, int steps) {
  Vector3 s = Vector3::Zero();
  const double h = dt / steps;
  auto f = [&](const Vector3& q) { return Vector3(v * std::cos(q(2)), v * std::sin(q(2)), omega); };
  for (int k = 0; k < steps; ++k) {
    const Vector3 k1 = f(s), k2 = f(s + 0.5 * h * k1), k3 = f(s + 0.5 * h * k2), k4 = f(s + h * k3);
    s += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return SE2(s(0), s(1), s(2));
}

TEST(UnicycleModel, IncrementMatchesFineStepIntegration) {
  const struct {
    double v, omega, dt;
  } cases[] = {{1.0, 0.0, 0.5}, {1.0, 1e-9, 0.5}, {0.8, 0.6, 1.0}, {-0.5, 2.5, 1.0}, {1.5, -3.0, 1.0},
               {0.0, 1.0, 0.3}, {0.3, 0.1, 0.02}};
  for (const auto& c : cases) {
    const SE2 exact = UnicycleModel::increment(c.v, c.omega, c.dt);
    const SE2 integrated = integrateUnicycleRk4(c.v, c.omega, c.dt, 4000);
    EXPECT_TRUE(exact.equals(integrated, 1e-11)) << "v=" << c.v << " omega=" << c.omega << ": " << exact << " vs "
                                                 << integrated;
  }
  // The semicircle: v = 1, ω = π over 1 s ends 2/π to the left, turned around.
  EXPECT_TRUE(UnicycleModel::increment(1.0, std::numbers::pi, 1.0).equals(SE2(0.0, 2.0 / std::numbers::pi,
                                                                              std::numbers::pi), 1e-12));
}

TEST(UnicycleModel, InputJacobianMatchesFineStepIntegration) {
  const struct {
    double v, omega, dt;
  } cases[] = {{1.0, 0.0, 0.5}, {0.8, 0.6, 1.0}, {-0.5, 2.5, 1.0}, {2.0, -1.2, 0.7}};
  for (const auto& c : cases) {
    Matrix32 G;
    UnicycleModel::increment(c.v, c.omega, c.dt, &G);
    const std::function<SE2(const Vector2&)> integrated = [&](const Vector2& u) {
      return integrateUnicycleRk4(u(0), u(1), c.dt, 2000);
    };
    const Matrix numerical = test::numericalDerivative<SE2, Vector2>(integrated, Vector2(c.v, c.omega), 1e-5);
    EXPECT_TRUE(matricesNear(G, numerical, 1e-7)) << "v=" << c.v << " omega=" << c.omega;
  }
}

TEST(UnicycleModel, CovarianceMatchesMonteCarloOfTheInputs) {
  const double v = 0.9, omega = 1.3, dt = 0.8, varV = 0.01, varW = 0.02;
  const UnicycleModel model(varV, varW, Vector3::Zero());
  const Odometry odometry = model.integrate(v, omega, dt);
  const SE2 mean = std::get<SE2>(odometry.increment);
  std::mt19937 rng(5);
  std::vector<Vector> errors;
  for (int s = 0; s < 200000; ++s) {
    const double vs = v + std::sqrt(varV) * standardNormal(rng);
    const double ws = omega + std::sqrt(varW) * standardNormal(rng);
    errors.push_back(mean.localCoordinates(UnicycleModel::increment(vs, ws, dt)));
  }
  const MonteCarlo mc = sampleCovariance(errors);
  const double scale = odometry.covariance.cwiseAbs().maxCoeff();
  EXPECT_TRUE(((odometry.covariance - mc.covariance).cwiseAbs().array() <=
               (5.0 * mc.standardError.array() + 5e-3 * scale))
                  .all())
      << "propagated:\n"
      << odometry.covariance << "\nMonte Carlo:\n"
      << mc.covariance;
}

TEST(UnicycleModel, FloorMakesTheCovariancePositiveDefinite) {
  const double dt = 0.1;
  const UnicycleModel exact(0.01, 0.02, Vector3::Zero());
  const Matrix rankTwo = exact.integrate(1.0, 0.5, dt).covariance;
  Eigen::SelfAdjointEigenSolver<Matrix> eigen(rankTwo);
  EXPECT_LT(std::abs(eigen.eigenvalues()(0)), 1e-12 * eigen.eigenvalues()(2));  // input noise alone: rank 2

  const UnicycleModel floored(0.01, 0.02);  // default floor
  const Matrix withFloor = floored.integrate(1.0, 0.5, dt).covariance;
  EXPECT_TRUE(matricesNear(withFloor - rankTwo, Matrix(dt * UnicycleModel::defaultFloor().asDiagonal()), 1e-15));
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix>(withFloor).eigenvalues()(0), 0.0);
  // With no input noise at all, the floor alone.
  const UnicycleModel floorOnly(0.0, 0.0, Vector3(1.0, 2.0, 3.0));
  EXPECT_TRUE(matricesNear(floorOnly.integrate(1.0, 0.5, 0.5).covariance,
                           Matrix(Vector3(0.5, 1.0, 1.5).asDiagonal()), 1e-15));
  // dt = 0: identity and zero covariance.
  const Odometry still = floored.integrate(1.0, 0.5, 0.0);
  EXPECT_TRUE(std::get<SE2>(still.increment).equals(SE2(), 0.0));
  EXPECT_EQ(still.covariance.cwiseAbs().maxCoeff(), 0.0);
}

TEST(UnicycleModel, RejectsInvalidInputs) {
  EXPECT_THROW(UnicycleModel(-1.0, 0.1), std::invalid_argument);
  EXPECT_THROW(UnicycleModel(0.1, std::nan("")), std::invalid_argument);
  EXPECT_THROW(UnicycleModel(0.1, 0.1, Vector3(0.0, -1e-3, 0.0)), std::invalid_argument);
  EXPECT_THROW(UnicycleModel::increment(1.0, 0.0, -0.1), std::invalid_argument);
  EXPECT_THROW(UnicycleModel::increment(std::nan(""), 0.0, 0.1), std::invalid_argument);
}

// ---- SE3 velocity -----------------------------------------------------------------------------------------------

/// RK4 on Ṙ = R ω^, ṫ = R v from the identity.
SE3 integrateTwistRk4(const Vector3& v, const Vector3& w, double dt, int steps) {
  Matrix3 R = Matrix3::Identity();
  Vector3 t = Vector3::Zero();
  const Matrix3 W = SO3::hat(w);
  const double h = dt / steps;
  for (int k = 0; k < steps; ++k) {
    const Matrix3 R1 = R * W, R2 = (R + 0.5 * h * R1) * W, R3 = (R + 0.5 * h * R2) * W, R4 = (R + h * R3) * W;
    const Vector3 t1 = R * v, t2 = (R + 0.5 * h * R1) * v, t3 = (R + 0.5 * h * R2) * v, t4 = (R + h * R3) * v;
    R += h / 6.0 * (R1 + 2.0 * R2 + 2.0 * R3 + R4);
    t += h / 6.0 * (t1 + 2.0 * t2 + 2.0 * t3 + t4);
  }
  return SE3(SO3(R), t);
}

TEST(VelocityModel3, IncrementMatchesFineStepIntegration) {
  const struct {
    Vector3 v, w;
    double dt;
  } cases[] = {{Vector3(1.0, 0.0, 0.0), Vector3::Zero(), 0.5},
               {Vector3(1.0, 0.2, -0.1), Vector3(0.1, -0.3, 0.8), 1.0},
               {Vector3(-0.4, 0.5, 0.3), Vector3(1.5, 0.7, -1.1), 1.0},
               {Vector3(0.2, 0.0, 0.1), Vector3(0.0, 0.0, 2.5), 0.9}};
  for (const auto& c : cases) {
    const SE3 exact = VelocityModel3::increment(c.v, c.w, c.dt);
    const SE3 integrated = integrateTwistRk4(c.v, c.w, c.dt, 4000);
    EXPECT_TRUE(exact.equals(integrated, 1e-11)) << exact << " vs " << integrated;
  }
}

TEST(VelocityModel3, InputJacobianMatchesCentralDifferences) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 20; ++trial) {
    Vector6 u;
    for (int i = 0; i < 6; ++i) u(i) = 1.5 * standardNormal(rng);
    const double dt = 0.1 + 0.9 * uniform01(rng);
    Matrix6 G;
    VelocityModel3::increment(u.head<3>(), u.tail<3>(), dt, &G);
    const std::function<SE3(const Vector6&)> f = [&](const Vector6& x) {
      return VelocityModel3::increment(x.head<3>(), x.tail<3>(), dt);
    };
    EXPECT_TRUE(matricesNear(G, test::numericalDerivative<SE3, Vector6>(f, u), 1e-7));
  }
}

TEST(VelocityModel3, CovarianceIsThePropagatedInputCovariancePlusFloor) {
  std::mt19937 rng(4);
  const Matrix inputCovariance = randomCovariance(6, 0.1, rng);
  Vector6 floor;
  floor << 1e-4, 2e-4, 3e-4, 1e-5, 2e-5, 3e-5;
  const VelocityModel3 model(Matrix6(inputCovariance), floor);
  const Vector3 v(1.0, 0.1, -0.2), w(0.3, -0.2, 0.9);
  const double dt = 0.4;
  Matrix6 G;
  VelocityModel3::increment(v, w, dt, &G);
  const Odometry odometry = model.integrate(v, w, dt);
  EXPECT_TRUE(matricesNear(odometry.covariance, G * inputCovariance * G.transpose() + Matrix(dt * floor.asDiagonal()),
                           1e-14));
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix>(odometry.covariance).eigenvalues()(0), 0.0);
  // The diagonal constructor is the same as a diagonal matrix.
  const VelocityModel3 diagonal(Vector3(0.01, 0.02, 0.03), Vector3(0.001, 0.002, 0.003));
  Vector6 variances;
  variances << 0.01, 0.02, 0.03, 0.001, 0.002, 0.003;
  EXPECT_TRUE(matricesNear(diagonal.inputCovariance(), Matrix(variances.asDiagonal()), 0.0));
  EXPECT_THROW(VelocityModel3(Matrix6(-Matrix6::Identity())), std::invalid_argument);
  EXPECT_THROW(VelocityModel3::increment(v, w, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
