#pragma once
// NormalEquations: the Gauss-Newton system  H δ = −g  of a factor graph, assembled directly into sparse storage.
//
// With every factor linearized at X (whitened error r_f, Jacobians J_f,k), the objective F = ½ Σ_f ‖r_f‖² has
//   g = Σ_f J_fᵀ r_f            (the gradient of F with respect to the right perturbations δ),
//   H = Σ_f J_fᵀ J_f            (its Gauss-Newton Hessian, the information matrix at X),
// and the step δ = −H⁻¹ g is applied as X ⊕ δ (Manifold<T>::retract per variable).
//
// Layout: variables are ordered by key; each is a block of its tangent dimension. H is held as the upper
// triangle of a compressed-column matrix whose pattern is built once from the factors' keys: for a block column
// b, the rows are the blocks a ≤ b that share a factor with b, each block stored densely (the diagonal block
// keeps its upper triangle). assemble() then writes J_aᵀJ_b straight into the value array at precomputed
// offsets: no triplets, no sorting, no allocation per iteration. The fill-reducing ordering belongs to the
// factorization (SparseCholesky), which keeps its symbolic analysis as long as the pattern is unchanged.

#include <Eigen/SparseCore>
#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"

namespace semslam {

class NormalEquations {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// Lays out H for `graph` over the variables its factors touch. Throws std::invalid_argument if a factor
  /// names a variable that `values` lacks, or names one variable twice.
  NormalEquations(const FactorGraph& graph, const Values& values);

  /// Linearizes every factor at `values`, fills H and g, and returns chi2 = Σ_f ‖r_f‖² (robust kernels:
  /// Σ ρ_f). `values` must hold the same variables, of the same types, as at construction.
  double assemble(const Values& values);

  /// Upper triangle of H (call assemble first).
  const SparseMatrix& hessian() const { return hessian_; }
  /// g = Jᵀr.
  const Vector& gradient() const { return gradient_; }
  /// Jᵀv = Σ_f J_fᵀ v_f at the last assemble(), for one vector v_f per factor of its whitened error's dimension (in
  /// graph order). Throws std::invalid_argument for a wrong count or dimension.
  Vector transposedJacobianTimes(const std::vector<Vector>& perFactor) const;
  /// Positions of H's diagonal entries in hessian().valuePtr(), in column order (for damping).
  const std::vector<int>& diagonalPositions() const { return diagonalPositions_; }

  int dimension() const { return dimension_; }
  /// Heap bytes held: the system, the per-factor linearizations and index tables (not the shared factors).
  std::size_t memoryBytes() const;
  const std::vector<Key>& keys() const { return keys_; }
  /// Column offset and dimension of a variable's block; throws std::out_of_range for an unknown key.
  int offset(Key key) const;
  int dimension(Key key) const;

  /// X ⊕ δ for the ordered variables; variables that no factor touches are copied unchanged.
  Values retract(const Values& values, const Vector& delta) const;

 private:
  int variableIndex(Key key) const;

  // Variables in key order.
  std::vector<Key> keys_;
  std::vector<int> offsets_;
  std::vector<int> dims_;
  int dimension_ = 0;

  // Per factor: its variable indices and, for each ordered pair (p, q) of its keys with index(p) ≤ index(q),
  // the row offset of block (p, q) inside the compressed columns of q.
  FactorGraph graph_;  // shares the factors
  std::vector<std::vector<int>> factorVariables_;
  std::vector<std::vector<int>> factorBlockRows_;
  std::vector<LinearizedFactor> linearized_;

  SparseMatrix hessian_;
  std::vector<int> diagonalPositions_;
  Vector gradient_;
};

}  // namespace semslam
