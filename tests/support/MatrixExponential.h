#pragma once
// expm(X): the matrix exponential Σ_k X^k / k!, by scaling and squaring of a Taylor series — an independent
// reference for the closed-form Exp of the Lie groups.
//   s = ⌈log2(‖X‖∞ / 0.5)⌉ squarings (0 when ‖X‖∞ ≤ 0.5), Y = X / 2^s, expm(X) = (Σ_{k<25} Y^k / k!)^(2^s).
// With ‖Y‖∞ ≤ 0.5 the truncated series is accurate to well below double rounding.

#include <cmath>

#include "semslam/geometry/Matrix.h"

namespace semslam::test {

template <int N>
MatrixN<N, N> expm(const MatrixN<N, N>& X) {
  using Square = MatrixN<N, N>;
  const double norm = X.cwiseAbs().rowwise().sum().maxCoeff();
  const int squarings = norm > 0.5 ? static_cast<int>(std::ceil(std::log2(norm / 0.5))) : 0;
  const Square Y = X / std::ldexp(1.0, squarings);
  Square result = Square::Identity(), term = Square::Identity();
  for (int k = 1; k < 25; ++k) {
    term = term * Y / k;
    result += term;
  }
  for (int i = 0; i < squarings; ++i) result = result * result;
  return result;
}

}  // namespace semslam::test
