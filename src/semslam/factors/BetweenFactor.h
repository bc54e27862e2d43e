#pragma once
// BetweenFactor<T>: a measured relative transformation z between two variables x_i and x_j (odometry, loop
// closures, g2o EDGE_SE2 / EDGE_SE3:QUAT).
//
// Error convention: e = Log(z⁻¹ · (x_i⁻¹ · x_j)) with the group's own exact log (translation first);
// for points, e = (x_j − x_i) − z. With E = z⁻¹ x_i⁻¹ x_j, the exact Jacobians are
//   ∂e/∂δ_j = Jr⁻¹(e),   ∂e/∂δ_i = −Jr⁻¹(e) · Ad(x_j⁻¹ x_i),
// (the chart's Jacobian Jr⁻¹ is kept, so the solution is a stationary point of this objective exactly).

#include "semslam/graph/NoiseModelFactor.h"

namespace semslam {

template <class T>
class BetweenFactor final : public NoiseModelFactor<Manifold<T>::kDim, T, T> {
  using Base = NoiseModelFactor<Manifold<T>::kDim, T, T>;

 public:
  using typename Base::ErrorVector;
  template <class V>
  using Jacobian = typename Base::template Jacobian<V>;

  BetweenFactor(Key i, Key j, const T& measured, SharedNoiseModel noiseModel)
      : Base(std::move(noiseModel), {i, j}), measured_(measured) {}

  const T& measured() const { return measured_; }

  ErrorVector evaluateError(const T& xi, const T& xj, Jacobian<T>* Hi, Jacobian<T>* Hj) const override {
    if constexpr (std::is_base_of_v<Eigen::MatrixBase<T>, T>) {
      if (Hi) *Hi = -Jacobian<T>::Identity();
      if (Hj) Hj->setIdentity();
      return (xj - xi) - measured_;
    } else {
      Jacobian<T> relativeI, relativeJ, logJacobian;
      const T relative = xi.between(xj, Hi ? &relativeI : nullptr, Hj ? &relativeJ : nullptr);
      // z⁻¹ · relative: the left factor is constant, so its Jacobian with respect to `relative` is I.
      const ErrorVector e = T::Log(measured_.between(relative), (Hi || Hj) ? &logJacobian : nullptr);
      if (Hi) *Hi = logJacobian * relativeI;
      if (Hj) *Hj = logJacobian * relativeJ;
      return e;
    }
  }

 private:
  T measured_;
};

}  // namespace semslam
