#include "semslam/solve/SparseCholesky.h"

#include <stdexcept>

namespace semslam {

SparseCholesky::SparseCholesky() {
  // A matrix that is not positive definite is reported through factorize()'s result, never printed: CHOLMOD's
  // print level 0 silences its own messages ("CHOLMOD error: not positive definite ..."), which would reach the
  // user before the explanation the solvers give (solve/UnconstrainedSystem.h).
  llt_.cholmod().print = 0;
  llt_.setMode(Eigen::CholmodAuto);
  // LLᵀ also in the simplicial case: an LDLᵀ factorization would accept a negative pivot, and a matrix that is
  // not positive definite must be reported (an unconstrained variable), never solved.
  llt_.cholmod().final_ll = 1;
}

void SparseCholesky::analyze(const SparseMatrix& upper) {
  llt_.analyzePattern(upper);
  analyzed_ = true;
}

bool SparseCholesky::factorize(const SparseMatrix& upper) {
  if (!analyzed_) analyze(upper);
  llt_.factorize(upper);
  return llt_.info() == Eigen::Success;
}

Vector SparseCholesky::solve(const Vector& b) const {
  Vector x = llt_.solve(b);
  if (llt_.info() != Eigen::Success) throw std::runtime_error("sparse Cholesky solve failed");
  return x;
}

Matrix SparseCholesky::solve(const Matrix& b) const {
  Matrix x = llt_.solve(b);
  if (llt_.info() != Eigen::Success) throw std::runtime_error("sparse Cholesky solve failed");
  return x;
}

double SparseCholesky::logDeterminant() const { return llt_.logDeterminant(); }

std::size_t SparseCholesky::memoryBytes() const { return llt_.cholmod().memory_inuse; }

}  // namespace semslam
