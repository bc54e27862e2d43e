// The rectangular maximum-weight assignment against brute force: same optimum, and on ties the same
// (lexicographically smallest) assignment.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <numeric>
#include <random>

#include "semslam/solve/HungarianAssignment.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

struct BruteForce {
  double best = -std::numeric_limits<double>::infinity();
  std::vector<int> bestAssignment;
};

// Enumerates assignments with exactly min(n, m) pairs in lexicographic order of rowToColumn, "unassigned" (-1)
// counting as larger than every column; keeps the first one with the largest total (exact comparison).
void enumerate(const Matrix& w, int row, std::vector<int>& current, std::vector<char>& used, int unassignedLeft,
               double total, BruteForce& out) {
  const int n = static_cast<int>(w.rows()), m = static_cast<int>(w.cols());
  if (row == n) {
    if (total > out.best) {
      out.best = total;
      out.bestAssignment = current;
    }
    return;
  }
  for (int j = 0; j < m; ++j) {
    if (used[j]) continue;
    used[j] = 1;
    current[row] = j;
    enumerate(w, row + 1, current, used, unassignedLeft, total + w(row, j), out);
    used[j] = 0;
  }
  if (unassignedLeft > 0) {
    current[row] = -1;
    enumerate(w, row + 1, current, used, unassignedLeft - 1, total, out);
  }
}

BruteForce bruteForce(const Matrix& w) {
  const int n = static_cast<int>(w.rows()), m = static_cast<int>(w.cols());
  BruteForce out;
  std::vector<int> current(n, -1);
  std::vector<char> used(m, 0);
  enumerate(w, 0, current, used, std::max(0, n - m), 0.0, out);
  return out;
}

void expectConsistent(const Assignment& a, const Matrix& w) {
  ASSERT_EQ(a.rowToColumn.size(), static_cast<std::size_t>(w.rows()));
  ASSERT_EQ(a.columnToRow.size(), static_cast<std::size_t>(w.cols()));
  int pairs = 0;
  double total = 0.0;
  for (int i = 0; i < w.rows(); ++i) {
    const int j = a.rowToColumn[i];
    if (j < 0) continue;
    ++pairs;
    total += w(i, j);
    EXPECT_EQ(a.columnToRow[j], i);
  }
  for (int j = 0; j < w.cols(); ++j) {
    if (a.columnToRow[j] >= 0) {
      EXPECT_EQ(a.rowToColumn[a.columnToRow[j]], j);
    }
  }
  EXPECT_EQ(pairs, std::min(w.rows(), w.cols()));
  EXPECT_NEAR(total, a.totalWeight, 1e-9);
}

/// A random weight matrix: its row and column counts drawn from `size` (rows first), its entries from `value`,
/// row by row.
template <class Size, class Value>
Matrix randomWeights(std::mt19937& rng, Size& size, Value& value) {
  const int n = size(rng), m = size(rng);
  Matrix w(n, m);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) w(i, j) = value(rng);
  return w;
}

TEST(HungarianAssignment, MatchesBruteForceOnSmallIntegerMatricesIncludingTies) {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> size(1, 6), value(0, 3);
  for (int trial = 0; trial < 600; ++trial) {
    const Matrix w = randomWeights(rng, size, value);
    const Assignment a = maximumWeightAssignment(w);
    const BruteForce b = bruteForce(w);
    expectConsistent(a, w);
    EXPECT_EQ(a.totalWeight, b.best) << "trial " << trial << "\n" << w;
    EXPECT_EQ(a.rowToColumn, b.bestAssignment) << "trial " << trial << "\n" << w;
  }
}

TEST(HungarianAssignment, MatchesBruteForceOnSmallRealMatricesWithNegativeWeights) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> size(1, 7);
  std::uniform_real_distribution<double> value(-5.0, 5.0);
  for (int trial = 0; trial < 300; ++trial) {
    const Matrix w = randomWeights(rng, size, value);
    const Assignment a = maximumWeightAssignment(w);
    const BruteForce b = bruteForce(w);
    expectConsistent(a, w);
    EXPECT_NEAR(a.totalWeight, b.best, 1e-9) << "trial " << trial;
    EXPECT_EQ(a.rowToColumn, b.bestAssignment) << "trial " << trial;
  }
}

TEST(HungarianAssignment, TiesGoToTheLexicographicallySmallestAssignment) {
  EXPECT_EQ(maximumWeightAssignment(Matrix::Zero(3, 3)).rowToColumn, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(maximumWeightAssignment(Matrix::Zero(2, 4)).rowToColumn, (std::vector<int>{0, 1}));
  EXPECT_EQ(maximumWeightAssignment(Matrix::Zero(4, 2)).rowToColumn, (std::vector<int>{0, 1, -1, -1}));
  Matrix w(2, 2);
  w << 1, 2, 3, 4;  // 1 + 4 = 2 + 3
  EXPECT_EQ(maximumWeightAssignment(w).rowToColumn, (std::vector<int>{0, 1}));
  // Lexicographic preference never costs weight: row 0 would like column 0, but only {1, 0} is optimal.
  Matrix v(2, 3);
  v << 5, 5, 0, 5, 0, 0;
  const Assignment a = maximumWeightAssignment(v);
  EXPECT_EQ(a.totalWeight, 10.0);
  EXPECT_EQ(a.rowToColumn, (std::vector<int>{1, 0}));
}

TEST(HungarianAssignment, KnownThreeByThree) {
  Matrix w(3, 3);
  w << 4, 1, 3,  //
      2, 0, 5,   //
      3, 2, 2;
  const Assignment a = maximumWeightAssignment(w);
  EXPECT_EQ(a.totalWeight, 11.0);
  EXPECT_EQ(a.rowToColumn, (std::vector<int>{0, 2, 1}));
}

TEST(HungarianAssignment, InvariantUnderPermutationsOnLargerMatrices) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> value(0.0, 100.0);
  const int n = 80, m = 120;
  Matrix w(n, m);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) w(i, j) = value(rng);
  const Assignment a = maximumWeightAssignment(w);
  expectConsistent(a, w);

  std::vector<int> rows(n), columns(m);
  std::iota(rows.begin(), rows.end(), 0);
  std::iota(columns.begin(), columns.end(), 0);
  std::shuffle(rows.begin(), rows.end(), rng);
  std::shuffle(columns.begin(), columns.end(), rng);
  Matrix permuted(n, m);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) permuted(i, j) = w(rows[i], columns[j]);
  const Assignment b = maximumWeightAssignment(permuted);
  EXPECT_NEAR(a.totalWeight, b.totalWeight, 1e-9);
  for (int i = 0; i < n; ++i) EXPECT_EQ(columns[b.rowToColumn[i]], a.rowToColumn[rows[i]]);

  // The transpose has the same optimum.
  EXPECT_NEAR(maximumWeightAssignment(w.transpose()).totalWeight, a.totalWeight, 1e-9);
}

TEST(HungarianAssignment, CubicTimeOnAFewHundredRows) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> value(0, 2);  // many ties: exercises the tie-breaking pass too
  const int n = 300;
  Matrix w(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) w(i, j) = value(rng);
  const auto start = std::chrono::steady_clock::now();
  const Assignment a = maximumWeightAssignment(w);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expectConsistent(a, w);
  EXPECT_EQ(a.totalWeight, 2.0 * n);  // a random 0..2 matrix this size has a perfect matching on its 2s
  EXPECT_LT(seconds, 5.0);
}

TEST(HungarianAssignment, EmptyAndInvalidInput) {
  const Assignment empty = maximumWeightAssignment(Matrix(0, 3));
  EXPECT_TRUE(empty.rowToColumn.empty());
  EXPECT_EQ(empty.columnToRow, (std::vector<int>{-1, -1, -1}));
  EXPECT_EQ(empty.totalWeight, 0.0);
  Matrix w = Matrix::Zero(2, 2);
  w(1, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(maximumWeightAssignment(w), InputError);
  w(1, 0) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(maximumWeightAssignment(w), InputError);
}

}  // namespace
}  // namespace semslam
