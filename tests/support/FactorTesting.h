#pragma once
// Checks a factor's analytic Jacobians against central finite differences of its whitened error, perturbing
// each variable on its manifold (right perturbation), exactly as the solvers use them.

#include <gtest/gtest.h>

#include "semslam/graph/Factor.h"

namespace semslam::test {

/// Numerical Jacobians of the whitened error of `factor` at `values`, one per key.
inline std::vector<Matrix> numericalFactorJacobians(const Factor& factor, const Values& values, double h = 1e-6) {
  std::vector<Matrix> jacobians;
  LinearizedFactor scratch;
  for (Key key : factor.keys()) {
    const int d = dimension(values.value(key));
    Matrix jacobian(factor.errorDimension(), d);
    for (int i = 0; i < d; ++i) {
      Vector delta = Vector::Zero(d);
      Values plus = values, minus = values;
      delta(i) = h;
      plus.update(key, retract(values.value(key), delta));
      delta(i) = -h;
      minus.update(key, retract(values.value(key), delta));
      factor.linearize(plus, scratch);
      const Vector errorPlus = scratch.whitenedError;
      factor.linearize(minus, scratch);
      jacobian.col(i) = (errorPlus - scratch.whitenedError) / (2.0 * h);
    }
    jacobians.push_back(jacobian);
  }
  return jacobians;
}

/// Expects every analytic Jacobian to match the numerical one to `tolerance` (absolute, max-norm), scaled by
/// max(1, ‖J‖∞) so that stiff (strongly whitened) factors are judged relatively.
inline void expectJacobiansMatch(const Factor& factor, const Values& values, double tolerance = 1e-6) {
  LinearizedFactor analytic;
  factor.linearize(values, analytic);
  const std::vector<Matrix> numerical = numericalFactorJacobians(factor, values);
  ASSERT_EQ(analytic.jacobians.size(), numerical.size());
  for (std::size_t k = 0; k < numerical.size(); ++k) {
    const double scale = std::max(1.0, numerical[k].cwiseAbs().maxCoeff());
    EXPECT_LE((analytic.jacobians[k] - numerical[k]).cwiseAbs().maxCoeff(), tolerance * scale)
        << "Jacobian " << k << " (" << keyToString(factor.keys()[k]) << ")\nanalytic:\n"
        << analytic.jacobians[k] << "\nnumerical:\n"
        << numerical[k];
  }
}

}  // namespace semslam::test
