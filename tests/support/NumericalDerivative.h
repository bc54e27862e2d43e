#pragma once
// Central finite differences on manifolds, for testing analytic Jacobians.
//
// For f: A -> B between manifolds (or vector spaces), the numerical Jacobian at a is
//   J[:, i] = ( local_B(f(a), f(a ⊕ h e_i)) - local_B(f(a), f(a ⊕ -h e_i)) ) / (2h),
// with the right perturbation a ⊕ δ = a · Exp(δ) and local_B(y, y') = Log(y^-1 y'), so it is the derivative
// in exactly the convention of the analytic Jacobians.

#include <functional>

#include "semslam/geometry/Manifold.h"

namespace semslam::test {

template <class Out, class In>
Matrix numericalDerivative(const std::function<Out(const In&)>& f, const In& x, double h = 1e-6) {
  using InTraits = Manifold<In>;
  using OutTraits = Manifold<Out>;
  const Out fx = f(x);
  const int inputDim = InTraits::dimension(x);
  const int outputDim = OutTraits::dimension(fx);
  Matrix jacobian(outputDim, inputDim);
  for (int i = 0; i < inputDim; ++i) {
    Vector delta = Vector::Zero(inputDim);
    delta(i) = h;
    const Vector plus = OutTraits::local(fx, f(InTraits::retract(x, delta)));
    delta(i) = -h;
    const Vector minus = OutTraits::local(fx, f(InTraits::retract(x, delta)));
    jacobian.col(i) = (plus - minus) / (2.0 * h);
  }
  return jacobian;
}

}  // namespace semslam::test
