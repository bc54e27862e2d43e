#pragma once
// The upper triangle of an n×n matrix as the n(n+1)/2 numbers of a file record, row-major:
// (0,0) (0,1) ... (0,n-1) (1,1) ... (n-1,n-1). Pose-graph files store information matrices (mirrored into the
// lower triangle) and square-root information matrices (lower triangle zero) this way.

#include <cstddef>
#include <vector>

#include "semslam/geometry/Matrix.h"

namespace semslam {

constexpr std::size_t triangularCount(int n) { return static_cast<std::size_t>(n * (n + 1) / 2); }

/// The symmetric matrix whose upper triangle is `entries` (row-major).
inline Matrix symmetricFromUpper(const std::vector<double>& entries, int n) {
  Matrix m(n, n);
  std::size_t k = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i; j < n; ++j) m(i, j) = m(j, i) = entries.at(k++);
  }
  return m;
}

/// The upper-triangular matrix whose upper triangle is `entries` (row-major); zero below the diagonal.
inline Matrix upperFromEntries(const std::vector<double>& entries, int n) {
  Matrix m = Matrix::Zero(n, n);
  std::size_t k = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i; j < n; ++j) m(i, j) = entries.at(k++);
  }
  return m;
}

/// The upper triangle of `m`, row-major.
inline std::vector<double> upperEntries(const Matrix& m) {
  std::vector<double> entries;
  entries.reserve(triangularCount(static_cast<int>(m.rows())));
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index j = i; j < m.cols(); ++j) entries.push_back(m(i, j));
  }
  return entries;
}

}  // namespace semslam
