#pragma once
// PriorFactor<T>: a Gaussian prior on one variable.
//
// Error convention: e = Log(z⁻¹ · x) for Lie groups (the tangent of x seen from the prior mean z, translation
// first), e = x − z for points. Jacobian: ∂e/∂δ = Jr⁻¹(e) for groups, I for points.

#include "semslam/graph/NoiseModelFactor.h"

namespace semslam {

template <class T>
class PriorFactor final : public NoiseModelFactor<Manifold<T>::kDim, T> {
  using Base = NoiseModelFactor<Manifold<T>::kDim, T>;

 public:
  using typename Base::ErrorVector;
  template <class V>
  using Jacobian = typename Base::template Jacobian<V>;

  PriorFactor(Key key, const T& prior, SharedNoiseModel noiseModel)
      : Base(std::move(noiseModel), {key}), prior_(prior) {}

  const T& prior() const { return prior_; }

  ErrorVector evaluateError(const T& x, Jacobian<T>* H) const override {
    if constexpr (std::is_base_of_v<Eigen::MatrixBase<T>, T>) {
      if (H) H->setIdentity();
      return x - prior_;
    } else {
      return T::Log(prior_.between(x), H);  // ∂/∂δ of Log(z⁻¹ x Exp(δ)) = Jr⁻¹(e)
    }
  }

 private:
  T prior_;
};

}  // namespace semslam
