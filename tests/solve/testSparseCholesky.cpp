// SparseCholesky (solve/SparseCholesky.h) on dense-enough matrices that CHOLMOD factors them supernodally: the
// solution and log-determinant against Eigen's dense LLᵀ, and "Threads": a factorization big enough for CHOLMOD's
// OpenMP regions (a supernode of hundreds of columns) leaves the process with the threads it had, on the main thread
// and on another one, which a team of CHOLMOD_OMP_NUM_THREADS would not (its workers stay alive in the runtime's
// pool once started).

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <cmath>
#include <filesystem>
#include <thread>

#include "semslam/solve/SparseCholesky.h"

namespace semslam {
namespace {

// The number of threads of this process (Linux: one entry per thread under /proc/self/task); -1 elsewhere.
int processThreads() {
  const std::filesystem::path tasks("/proc/self/task");
  if (!std::filesystem::is_directory(tasks)) return -1;
  int count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(tasks)) ++count;
  return count;
}

// A dense symmetric positive definite n × n matrix, B Bᵀ + n I with B's entries in [-1, 1] from a fixed rule.
Matrix denseSpd(int n) {
  Matrix b(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) b(i, j) = std::sin(0.7 * i + 1.3 * j + 0.1 * i * j);
  }
  return b * b.transpose() + n * Matrix::Identity(n, n);
}

SparseCholesky::SparseMatrix upperOf(const Matrix& dense) {
  return dense.triangularView<Eigen::Upper>().toDenseMatrix().sparseView();
}

TEST(SparseCholesky, ADenseMatrixIsSolvedAsEigensDenseFactorizationSolvesIt) {
  const Matrix h = denseSpd(300);
  Vector b(300);
  for (int i = 0; i < 300; ++i) b(i) = std::cos(0.3 * i);
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factorize(upperOf(h)));
  const Eigen::LLT<Matrix> dense(h);
  EXPECT_LT((cholesky.solve(b) - dense.solve(b)).norm(), 1e-12 * dense.solve(b).norm());
  EXPECT_NEAR(cholesky.logDeterminant(), 2.0 * dense.matrixLLT().diagonal().array().log().sum(), 1e-9);
}

TEST(SparseCholesky, AFactorizationStartsNoThread) {
  const int before = processThreads();
  if (before < 0) GTEST_SKIP() << "/proc/self/task is not there: the process's threads cannot be counted";
  const SparseCholesky::SparseMatrix upper = upperOf(denseSpd(400));
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factorize(upper));
  ASSERT_TRUE(cholesky.factorize(upper));
  EXPECT_EQ(processThreads(), before) << "CHOLMOD's OpenMP regions ran with a team on the calling thread";

  // On another thread too (the setting is per thread, so each one makes its own calls serial).
  int during = 0;
  std::thread other([&] {
    SparseCholesky onOther;
    if (onOther.factorize(upper)) during = processThreads();
  });
  other.join();
  EXPECT_EQ(during, before + 1) << "a factorization on a second thread started threads of its own";
}

}  // namespace
}  // namespace semslam
