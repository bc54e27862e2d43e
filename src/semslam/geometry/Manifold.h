#pragma once
// Manifold traits: one uniform way for the graph and the solvers to perturb any variable type.
//
// Every variable type T of a factor graph is a manifold with a fixed tangent dimension kDim and
//   retract(x, δ) = x ⊕ δ   (right perturbation: x · Exp(δ) for Lie groups, x + δ for vectors),
//   local(x, y)   = y ⊖ x   (the inverse: Log(x^-1 · y) for Lie groups, y - x for vectors),
// so that local(x, retract(x, δ)) = δ for small δ. Tangent order is translation first (SE2: x, y, θ).
//
// Lie group classes (SO2, SE2, SO3, SE3) provide `static constexpr int kDim`, `retract(δ)` and
// `localCoordinates(y)` as members; fixed-size Eigen vectors are their own tangent space.

#include <type_traits>

#include "semslam/geometry/Matrix.h"

namespace semslam {

template <class T, class Enable = void>
struct Manifold {
  static constexpr int kDim = T::kDim;
  using Tangent = VectorN<kDim>;
  static int dimension(const T&) { return kDim; }
  static T retract(const T& x, const Eigen::Ref<const Vector>& delta) { return x.retract(Tangent(delta)); }
  static Tangent local(const T& x, const T& y) { return x.localCoordinates(y); }
};

/// Fixed-size Eigen column vectors (points, scalars as Vector1).
template <class T>
struct Manifold<T, std::enable_if_t<std::is_base_of_v<Eigen::MatrixBase<T>, T> && T::ColsAtCompileTime == 1 &&
                                    T::RowsAtCompileTime != Eigen::Dynamic>> {
  static constexpr int kDim = T::RowsAtCompileTime;
  using Tangent = VectorN<kDim>;
  static int dimension(const T&) { return kDim; }
  static T retract(const T& x, const Eigen::Ref<const Vector>& delta) { return x + delta; }
  static Tangent local(const T& x, const T& y) { return y - x; }
};

}  // namespace semslam
