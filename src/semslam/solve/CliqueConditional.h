#pragma once
// CliqueConditional: one clique of a Bayes tree (Kaess et al., IJRR 2012, Sec. III), in square-root information
// form, obtained by partial dense Cholesky elimination of the clique's joint Gauss-Newton system.
//
// The clique's variables are its frontals F (eliminated here, in order) and its separator S (eliminated higher up
// the tree). Gathering every factor assigned to the clique and the marginal factors its children pass up gives a
// dense symmetric system over (F, S) in the variables' updates Δ from the linearization point:
//
//     [A_FF  A_FS] [Δ_F]   [b_F]
//     [A_SF  A_SS] [Δ_S] = [b_S],        A = Σ JᵀJ,  b = −Σ Jᵀr  (whitened Jacobians and errors).
//
// Eliminating F:  RᵀR = A_FF (R upper triangular),  T = R⁻ᵀ A_FS,  z = R⁻ᵀ b_F, which is the conditional density
// p(Δ_F | Δ_S) ∝ exp(−½ ‖R Δ_F + T Δ_S − z‖²), and the marginal factor on S passed to the parent clique:
//
//     Ā = A_SS − TᵀT,   b̄ = b_S − Tᵀz        (the Schur complement: the subtree summarised on its separator).
//
// Back-substitution top-down gives Δ_F = R⁻¹ (z − T Δ_S). Stacking the (R, T) rows of every clique in elimination
// order is exactly the upper Cholesky factor of the whole system's Hessian under that ordering.
//
// Invariants: R is nf×nf upper triangular with a positive diagonal; T is nf×ns; z has nf rows; Ā is ns×ns
// symmetric (both triangles stored); b̄ has ns rows. Immutable once built: forks of a smoother share it.

#include <vector>

#include "semslam/geometry/Matrix.h"

namespace semslam {

struct CliqueConditional {
  CliqueConditional() = default;
  CliqueConditional(const CliqueConditional&) = delete;  // the maps point into this object's own storage
  CliqueConditional& operator=(const CliqueConditional&) = delete;

  // Views of one contiguous allocation (one per clique instead of five: cliques are many and small).
  Eigen::Map<Matrix> R{nullptr, 0, 0};
  Eigen::Map<Matrix> T{nullptr, 0, 0};
  Eigen::Map<Vector> z{nullptr, 0};
  Eigen::Map<Matrix> marginalInformation{nullptr, 0, 0};  // Ā
  Eigen::Map<Vector> marginalVector{nullptr, 0};          // b̄

  /// Eliminates the first `frontalDimension` scalar variables of the symmetric system (A, b) (both triangles of A
  /// filled). Returns false, leaving `out` unspecified, if A_FF is not numerically positive definite (a variable
  /// that the factors do not constrain). A is overwritten.
  static bool eliminate(Eigen::Ref<Matrix> A, Eigen::Ref<const Vector> b, int frontalDimension,
                        CliqueConditional& out);

  /// Δ_F = R⁻¹ (z − T Δ_S), into `frontalDelta` (of the frontal dimension).
  void solve(Eigen::Ref<const Vector> separatorDelta, Eigen::Ref<Vector> frontalDelta) const;

  /// Heap bytes held (R, T, z).
  std::size_t memoryBytes() const { return storage_.capacity() * sizeof(double); }

 private:
  void allocate(int frontalDimension, int separatorDimension);
  std::vector<double> storage_;
};

}  // namespace semslam
