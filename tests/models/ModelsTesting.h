#pragma once
// Helpers shared by the models tests: matrix comparison with a readable failure, and central differences of
// angle-valued functions (wrapped, so that a result near ±π does not jump by 2π between the two sides).

#include <gtest/gtest.h>

#include <functional>

#include "semslam/geometry/Manifold.h"
#include "semslam/models/Angle.h"

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

}  // namespace semslam::test
