#pragma once
// Helpers shared by the models tests: matrix comparison with a readable failure, and central differences of
// angle-valued functions (wrapped, so that a result near ±π does not jump by 2π between the two sides), and seeded
// random poses.

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "semslam/geometry/Manifold.h"
#include "semslam/geometry/SE3.h"
#include "semslam/models/Angle.h"
#include "semslam/models/Sampling.h"

namespace semslam::test {

inline ::testing::AssertionResult matricesNear(const Matrix& actual, const Matrix& expected, double tol) {
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols()) {
    return ::testing::AssertionFailure() << "sizes differ: " << actual.rows() << "x" << actual.cols() << " vs "
                                         << expected.rows() << "x" << expected.cols();
  }
  const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
  const double error = (actual - expected).cwiseAbs().maxCoeff();
  if (error <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "max difference " << error << " > " << tol << " * " << scale
                                       << "\nactual:\n"
                                       << actual << "\nexpected:\n"
                                       << expected;
}

/// d f / d δ for an angle-valued f of a manifold variable, by central differences with wrapped differences.
template <class In>
Matrix numericalAngleDerivative(const std::function<double(const In&)>& f, const In& x, double h = 1e-6) {
  const int d = Manifold<In>::dimension(x);
  Matrix J(1, d);
  for (int i = 0; i < d; ++i) {
    Vector delta = Vector::Zero(d);
    delta(i) = h;
    const double plus = f(Manifold<In>::retract(x, delta));
    delta(i) = -h;
    const double minus = f(Manifold<In>::retract(x, delta));
    J(0, i) = wrapAngle(plus - minus) / (2.0 * h);
  }
  return J;
}

/// Uniform in [a, b), from uniform01 (Sampling.h).
inline double uniform(std::mt19937& rng, double a, double b) { return a + (b - a) * uniform01(rng); }

/// A random pose: rotation by an angle uniform in [−3.1, 3.1] about an axis with components uniform in [−1, 1],
/// translation uniform in [−translation, translation]³.
inline SE3 randomSE3(std::mt19937& rng, double translation) {
  const Vector3 axis(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  return SE3(SO3::fromAxisAngle(axis, uniform(rng, -3.1, 3.1)),
             Point3(uniform(rng, -translation, translation), uniform(rng, -translation, translation),
                    uniform(rng, -translation, translation)));
}

}  // namespace semslam::test
