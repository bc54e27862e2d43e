#include "semslam/solve/HungarianAssignment.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>

#include "semslam/core/InputError.h"

namespace semslam {
namespace {

// Minimum-cost perfect matching of the square cost matrix `cost` (shortest augmenting paths with potentials).
// Returns the column of each row and leaves optimal dual potentials in u (rows) and v (columns).
std::vector<int> solveSquare(const Matrix& cost, std::vector<double>& u, std::vector<double>& v) {
  const int n = static_cast<int>(cost.rows());
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // Index 0 of the column arrays is a virtual column from which each new row's search starts; rows and columns
  // are 1-based inside this function.
  std::vector<double> rowPotential(n + 1, 0.0), columnPotential(n + 1, 0.0);
  std::vector<int> owner(n + 1, 0);  // owner[j]: the row matched to column j (0: none)
  std::vector<int> previous(n + 1, 0);
  std::vector<double> distance(n + 1);
  std::vector<char> done(n + 1);

  for (int row = 1; row <= n; ++row) {
    owner[0] = row;
    int column = 0;
    std::fill(distance.begin(), distance.end(), kInfinity);
    std::fill(done.begin(), done.end(), 0);
    do {
      done[column] = 1;
      const int current = owner[column];
      double delta = kInfinity;
      int next = 0;
      for (int j = 1; j <= n; ++j) {
        if (done[j]) continue;
        const double reduced = cost(current - 1, j - 1) - rowPotential[current] - columnPotential[j];
        if (reduced < distance[j]) {
          distance[j] = reduced;
          previous[j] = column;
        }
        if (distance[j] < delta) {  // strict: the smallest column index wins a tie
          delta = distance[j];
          next = j;
        }
      }
      for (int j = 0; j <= n; ++j) {
        if (done[j]) {
          rowPotential[owner[j]] += delta;
          columnPotential[j] -= delta;
        } else {
          distance[j] -= delta;
        }
      }
      column = next;
    } while (owner[column] != 0);
    // Augment along the path back to the virtual column.
    do {
      const int back = previous[column];
      owner[column] = owner[back];
      column = back;
    } while (column != 0);
  }

  std::vector<int> match(n, -1);
  for (int j = 1; j <= n; ++j) match[owner[j] - 1] = j - 1;
  u.assign(rowPotential.begin() + 1, rowPotential.end());
  v.assign(columnPotential.begin() + 1, columnPotential.end());
  return match;
}

// Turns the optimal matching `match` into the lexicographically smallest optimal one (see the header).
void lexicographicallySmallest(const Matrix& cost, const std::vector<double>& u, const std::vector<double>& v,
                               double tolerance, std::vector<int>& match) {
  const int n = static_cast<int>(match.size());
  std::vector<int> owner(n);
  for (int i = 0; i < n; ++i) owner[match[i]] = i;
  const auto tight = [&](int row, int column) {
    return match[row] == column || cost(row, column) - u[row] - v[column] <= tolerance;
  };

  std::vector<char> fixedRow(n, 0), fixedColumn(n, 0), reached(n);
  std::vector<int> next(n);
  std::deque<int> queue;
  for (int i = 0; i < n; ++i) {
    const int target = match[i];
    // Columns c whose owner can be moved, along tight pairs of free rows, so that the chain ends by taking
    // `target` (which row i gives up): then row i may take c instead. next[c] is the column c's owner moves to.
    std::fill(reached.begin(), reached.end(), 0);
    reached[target] = 1;
    queue.assign(1, target);
    while (!queue.empty()) {
      const int column = queue.front();
      queue.pop_front();
      for (int row = 0; row < n; ++row) {
        if (fixedRow[row] || row == i || owner[column] == row || !tight(row, column)) continue;
        const int freed = match[row];
        if (reached[freed]) continue;
        reached[freed] = 1;
        next[freed] = column;
        queue.push_back(freed);
      }
    }
    int best = target;
    for (int column = 0; column < target; ++column) {
      if (!fixedColumn[column] && reached[column] && tight(i, column)) {
        best = column;
        break;
      }
    }
    if (best != target) {
      std::vector<int> chain;  // best, next[best], ..., target
      for (int column = best; column != target; column = next[column]) chain.push_back(column);
      chain.push_back(target);
      std::vector<int> movers(chain.size() - 1);
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) movers[k] = owner[chain[k]];
      for (std::size_t k = 0; k < movers.size(); ++k) {
        match[movers[k]] = chain[k + 1];
        owner[chain[k + 1]] = movers[k];
      }
      match[i] = best;
      owner[best] = i;
    }
    fixedRow[i] = 1;
    fixedColumn[match[i]] = 1;
  }
}

}  // namespace

Assignment maximumWeightAssignment(const Matrix& weights) {
  const int rows = static_cast<int>(weights.rows());
  const int columns = static_cast<int>(weights.cols());
  Assignment result;
  result.rowToColumn.assign(rows, -1);
  result.columnToRow.assign(columns, -1);
  if (rows == 0 || columns == 0) return result;
  if (!weights.allFinite()) throw InputError("assignment: the weight matrix has a non-finite entry");

  const int n = std::max(rows, columns);
  Matrix cost = Matrix::Zero(n, n);
  cost.topLeftCorner(rows, columns) = -weights;
  const double scale = std::max(1.0, weights.cwiseAbs().maxCoeff());
  const double tolerance = 1e-12 * static_cast<double>(n) * scale;

  std::vector<double> u, v;
  std::vector<int> match = solveSquare(cost, u, v);
  lexicographicallySmallest(cost, u, v, tolerance, match);

  for (int i = 0; i < rows; ++i) {
    const int j = match[i];
    if (j >= columns) continue;
    result.rowToColumn[i] = j;
    result.columnToRow[j] = i;
    result.totalWeight += weights(i, j);
  }
  return result;
}

}  // namespace semslam
