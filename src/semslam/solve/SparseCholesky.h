#pragma once
// SparseCholesky: P H Pᵀ = L Lᵀ (or L D Lᵀ) for a sparse symmetric positive definite H given by its upper
// triangle, with SuiteSparse CHOLMOD (through Eigen's CholmodSupport) under CHOLMOD's fill-reducing ordering P
// (AMD, or METIS/nested dissection where that fills less). CHOLMOD chooses between its simplicial and supernodal
// factorizations from the symbolic factor (CHOLMOD_AUTO): simplicial wins on the thin factors of 2D pose chains
// (manhattan: 5.7 against 8.0 ms per factorization), supernodal on dense ones (sphere2500: 63 against 200 ms).
//
// analyze() computes the ordering and the symbolic factor once per sparsity pattern; factorize() may then be
// called for any matrix with that pattern (each Gauss-Newton or Levenberg-Marquardt iteration).

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

#include "semslam/geometry/Matrix.h"

namespace semslam {

class SparseCholesky {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  SparseCholesky();

  /// Symbolic analysis of the pattern of `upper` (its upper triangle).
  void analyze(const SparseMatrix& upper);
  /// Numeric factorization; returns false if the matrix is not (numerically) positive definite.
  bool factorize(const SparseMatrix& upper);
  bool analyzed() const { return analyzed_; }
  /// Bytes CHOLMOD holds for this factorization (its own count of what it allocated).
  std::size_t memoryBytes() const;

  /// H⁻¹ b, and H⁻¹ B column by column (after a successful factorize).
  Vector solve(const Vector& b) const;
  Matrix solve(const Matrix& b) const;
  /// ln det H = 2 Σ ln L_ii (after a successful factorize; the ordering P does not change it).
  double logDeterminant() const;

 private:
  mutable Eigen::CholmodDecomposition<SparseMatrix, Eigen::Upper> llt_;  // mutable: cholmod() is not const
  bool analyzed_ = false;
};

}  // namespace semslam
