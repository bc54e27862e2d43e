// SymbolicElimination against dense boolean Gaussian elimination of random patterns: the columns are exactly the
// factor's structure, and the cliques form a valid Bayes tree (every variable once, separators within the parent).

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "semslam/solve/SymbolicElimination.h"

using namespace semslam;

namespace {

/// struct(k) by eliminating a dense boolean matrix: eliminating k connects all its later neighbours.
std::vector<std::vector<int>> denseColumns(int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<char>> adjacent(n, std::vector<char>(n, 0));
  for (const auto& [a, b] : edges) adjacent[a][b] = adjacent[b][a] = 1;
  std::vector<std::vector<int>> columns(n);
  for (int k = 0; k < n; ++k) {
    for (int j = k + 1; j < n; ++j) {
      if (adjacent[k][j]) columns[k].push_back(j);
    }
    for (int a : columns[k]) {
      for (int b : columns[k]) {
        if (a != b) adjacent[a][b] = 1;
      }
    }
  }
  return columns;
}

void checkBayesTree(const SymbolicElimination& symbolic) {
  std::vector<int> seen(symbolic.variableCount(), 0);
  for (int c = 0; c < symbolic.cliqueCount(); ++c) {
    const auto& frontals = symbolic.frontals(c);
    const auto& separator = symbolic.separator(c);
    ASSERT_FALSE(frontals.empty());
    EXPECT_TRUE(std::is_sorted(frontals.begin(), frontals.end()));
    EXPECT_TRUE(std::is_sorted(separator.begin(), separator.end()));
    for (int f : frontals) {
      ++seen[f];
      EXPECT_EQ(symbolic.cliqueOf(f), c);
      // Every frontal's column lies in the clique (later frontals and the separator).
      for (int j : symbolic.column(f)) {
        const bool inClique = std::binary_search(separator.begin(), separator.end(), j) ||
                              (symbolic.cliqueOf(j) == c && j > f);
        EXPECT_TRUE(inClique) << "variable " << j << " of column " << f;
      }
    }
    const int parent = symbolic.parent(c);
    if (parent < 0) {
      EXPECT_TRUE(separator.empty());
      continue;
    }
    EXPECT_LT(frontals.back(), symbolic.frontals(parent).back());
    std::set<int> parentVariables(symbolic.frontals(parent).begin(), symbolic.frontals(parent).end());
    parentVariables.insert(symbolic.separator(parent).begin(), symbolic.separator(parent).end());
    for (int s : separator) EXPECT_TRUE(parentVariables.count(s)) << "separator variable " << s;
    EXPECT_EQ(symbolic.cliqueOf(separator.front()), parent);
  }
  for (int count : seen) EXPECT_EQ(count, 1);
}

}  // namespace

TEST(SymbolicElimination, ColumnsEqualDenseEliminationAndCliquesFormABayesTree) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 5 + trial;
    std::uniform_int_distribution<int> pick(0, n - 1);
    std::vector<std::pair<int, int>> edges;
    for (int k = 1; k < n; ++k) edges.emplace_back(k - 1, k);  // connected: a chain
    for (int e = 0; e < n / 2; ++e) {
      const int a = pick(rng);
      const int b = pick(rng);
      if (a != b) edges.emplace_back(a, b);
    }
    std::vector<std::vector<int>> later(n);
    for (const auto& [a, b] : edges) later[std::min(a, b)].push_back(std::max(a, b));
    const auto expected = denseColumns(n, edges);
    for (const auto& [frontals, zeros] : {std::pair{1, 0.0}, std::pair{4, 0.5}, std::pair{1000, 1.0}}) {
      SymbolicElimination symbolic;
      symbolic.eliminate(later, frontals, zeros);
      for (int k = 0; k < n; ++k) EXPECT_EQ(symbolic.column(k), expected[k]) << "trial " << trial << " column " << k;
      checkBayesTree(symbolic);
      if (frontals == 1000) EXPECT_EQ(symbolic.cliqueCount(), 1);  // a connected pattern amalgamates to one clique
    }
  }
}

TEST(SymbolicElimination, AChainIsAChainOfCliques) {
  // x0 - x1 - x2 - x3 in order: struct(k) = {k+1}. Only x2 has its parent's column plus its parent (struct(3) is
  // empty), so the fundamental cliques are {2, 3}, then {1 | 2}, then {0 | 1}: the Bayes tree of a chain.
  const std::vector<std::vector<int>> later = {{1}, {2}, {3}, {}};
  SymbolicElimination symbolic;
  symbolic.eliminate(later, 1, 0.0);
  ASSERT_EQ(symbolic.cliqueCount(), 3);
  const int root = symbolic.cliqueOf(3);
  EXPECT_EQ(symbolic.frontals(root), (std::vector<int>{2, 3}));
  EXPECT_EQ(symbolic.separator(symbolic.cliqueOf(1)), (std::vector<int>{2}));
  EXPECT_EQ(symbolic.separator(symbolic.cliqueOf(0)), (std::vector<int>{1}));
  EXPECT_EQ(symbolic.parent(symbolic.cliqueOf(0)), symbolic.cliqueOf(1));
  checkBayesTree(symbolic);
}

TEST(SymbolicElimination, AStarKeepsItsLeavesApartWithoutRelaxation) {
  // Leaves 0, 1, 2 each joined to the hub 3: three leaf cliques with separator {3} under a root clique {3}; the
  // first leaf processed joins the hub's clique (fundamental), the others cannot.
  const std::vector<std::vector<int>> later = {{3}, {3}, {3}, {}};
  SymbolicElimination symbolic;
  symbolic.eliminate(later, 1, 0.0);
  EXPECT_EQ(symbolic.cliqueCount(), 3);
  checkBayesTree(symbolic);
}
