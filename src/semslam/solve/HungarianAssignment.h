#pragma once
// The rectangular assignment problem, maximising total weight (Kuhn-Munkres / Hungarian method, in the
// shortest-augmenting-path form with dual potentials, O(N³) with N = max(rows, columns)).
//
// Problem: given weights w_ij (n rows, m columns, any finite reals), choose a set of pairs (i, j), each row and
// each column in at most one pair, with exactly min(n, m) pairs (every row is assigned when n ≤ m, every column
// when n ≥ m), maximising Σ w_ij over the chosen pairs.
//
// Method: the matrix is padded to N x N with zero weights and solved as the minimum-cost perfect matching with
// cost c_ij = −w_ij. Rows are added one at a time; each is connected by a shortest augmenting path in the reduced
// costs c_ij − u_i − v_j ≥ 0 (Dijkstra on a dense graph, O(N²) per row), and the potentials are updated so that
// reduced costs stay non-negative and are zero on matched pairs. At the end (u, v) is an optimal solution of the
// dual LP  max Σu_i + Σv_j  s.t.  u_i + v_j ≤ c_ij.
//
// Deterministic tie-breaking. By complementary slackness, the optimal assignments are exactly the perfect
// matchings that use only "tight" pairs (reduced cost 0). Among them this function returns the one whose
// row-to-column vector is lexicographically smallest when "unassigned" counts as larger than every column: row 0
// takes the smallest column it can take in any optimal assignment, then row 1 given that, and so on. It is found
// in O(N³) by fixing rows in order and moving the current matching along an alternating cycle of tight pairs
// (one reverse breadth-first search per row). The answer therefore depends only on the weights and their order,
// never on the path the solver took. Reduced costs within 1e-12 · N · max(1, max|w|) of zero count as tight, so
// weights that differ by less than that are treated as ties; integer-valued weights (counts) are exact.
//
// Non-finite weights throw InputError. An empty matrix (no rows or no columns) gives an empty assignment.

#include <vector>

#include "semslam/geometry/Matrix.h"

namespace semslam {

struct Assignment {
  std::vector<int> rowToColumn;  ///< the column assigned to each row, or -1
  std::vector<int> columnToRow;  ///< the row assigned to each column, or -1
  double totalWeight = 0.0;      ///< Σ w_ij over the assigned pairs
};

/// The maximum-weight assignment of `weights` (rows x columns) with min(rows, columns) pairs; among optimal
/// assignments the lexicographically smallest (see above).
Assignment maximumWeightAssignment(const Matrix& weights);

}  // namespace semslam
