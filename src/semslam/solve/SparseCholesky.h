#pragma once
// SparseCholesky: P H Pᵀ = L Lᵀ (or L D Lᵀ) for a sparse symmetric positive definite H given by its upper
// triangle, with SuiteSparse CHOLMOD (through Eigen's CholmodSupport) under CHOLMOD's fill-reducing ordering P
// (AMD, or METIS/nested dissection where that fills less). CHOLMOD chooses between its simplicial and supernodal
// factorizations from the symbolic factor (CHOLMOD_AUTO): simplicial wins on the thin factors of 2D pose chains
// (manhattan: 5.7 against 8.0 ms per factorization), supernodal on dense ones (sphere2500: 63 against 200 ms).
//
// analyze() computes the ordering and the symbolic factor once per sparsity pattern; factorize() may then be
// called for any matrix with that pattern (each Gauss-Newton or Levenberg-Marquardt iteration).
//
// Threads: every call runs on the calling thread only. Debian's CHOLMOD 3 (SuiteSparse 5) runs loops of its
// supernodal factorization as OpenMP parallel regions with a team fixed at compile time (CHOLMOD_OMP_NUM_THREADS =
// 4), whatever the machine has; on the 2-core machines of docs/results.md, with two runs side by side, that is 8
// threads on 2 cores, and the wake-ups cost more than the loops save (with the regions serial, on an idle 2-core
// machine: mm-nh on Starry Night 0.56 × the wall time, sphere2500's batch solve 0.79 ×, the same outputs byte for
// byte; docs/benchmarks.md, "Threads"). semslam parallelises across runs instead (studies' jobs, MPI ranks), so each
// call makes the OpenMP regions CHOLMOD starts serial: it sets the calling thread's max-active-levels to 0 in the
// OpenMP runtime CHOLMOD was linked with, and restores it after. The setting is per thread (OpenMP 5.0's data
// environment), so a host program's own OpenMP use on other threads is untouched; with a CHOLMOD built without
// OpenMP there is nothing to set. The factor does not depend on the team size: those loops are independent updates.

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
