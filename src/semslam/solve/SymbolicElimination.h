#pragma once
// SymbolicElimination: the sparsity structure of the Cholesky factor of a symmetric pattern under a given
// elimination order, grouped into the cliques of a Bayes tree (Kaess et al., IJRR 2012, Sec. III; the column
// structures and elimination tree as in Davis, "Direct Methods for Sparse Linear Systems", SIAM 2006, ch. 4).
//
// Variables are numbered by their elimination position 0..n−1. The column of k, struct(k), is the set of later
// variables that the factor's column k touches: k's later neighbours in the pattern, and the columns of k's
// children in the elimination tree (less k). The parent of k is the first variable of struct(k).
//
// Cliques are supernodes: k joins the clique C of its parent p when
//   - fundamentally, struct(k) = {p} ∪ struct(p) and p still heads C (no explicit zero is stored), or
//   - relaxed (as CHOLMOD's amalgamation), C has fewer than `relaxedFrontals` frontals and k's row in C would be
//     at most a fraction `relaxedZeros` of explicit zeros: struct(k) ⊆ {p} ∪ struct(p) always, so k's row in C is
//     exact, only padded with zeros.
// A clique's separator is the union of its frontals' columns, less its frontals; its parent is the clique of the
// first separator variable. Invariants (tested): every variable is a frontal of exactly one clique; frontals and
// separators are sorted; a clique's separator lies within its parent's frontals and separator; a child's frontals
// precede its parent's last frontal.

#include <vector>

namespace semslam {

class SymbolicElimination {
 public:
  /// `later[k]` lists the neighbours of k that come after it (duplicates allowed). Replaces any earlier result;
  /// storage is reused across calls.
  void eliminate(const std::vector<std::vector<int>>& later, int relaxedFrontals, double relaxedZeros);

  int variableCount() const { return static_cast<int>(cliqueOf_.size()); }
  int cliqueCount() const { return cliqueCount_; }
  const std::vector<int>& column(int variable) const { return columns_[variable]; }
  int cliqueOf(int variable) const { return cliqueOf_[variable]; }
  const std::vector<int>& frontals(int clique) const { return frontals_[clique]; }
  const std::vector<int>& separator(int clique) const { return separators_[clique]; }
  /// −1 for a root.
  int parent(int clique) const { return parents_[clique]; }

 private:
  std::vector<std::vector<int>> columns_;
  std::vector<std::vector<int>> treeChildren_;
  std::vector<int> treeParent_;
  std::vector<int> marker_;
  std::vector<int> cliqueOf_;
  std::vector<int> head_;
  std::vector<int> cliqueSize_;
  std::vector<std::vector<int>> frontals_;
  std::vector<std::vector<int>> separators_;
  std::vector<int> parents_;
  int cliqueCount_ = 0;
};

}  // namespace semslam
