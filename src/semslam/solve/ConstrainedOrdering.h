#pragma once
// ConstrainedOrdering: a fill-reducing elimination ordering of a symmetric sparsity pattern in which some
// variables are forced to come last, by SuiteSparse's CAMD (constrained approximate minimum degree; Amestoy,
// Davis and Duff, "Algorithm 837: AMD", ACM TOMS 2004, with the constraint sets of CAMD).
//
// iSAM2 (Kaess et al., IJRR 2012, Sec. V.B) orders the re-eliminated part of its Bayes tree with the variables of
// the newest factors constrained last, so that they sit in the root clique and the next update, which most likely
// touches them again, re-eliminates as little as possible.
//
// The pattern is given as neighbour lists over variables 0..n−1 (either or both directions of an edge; self
// edges and duplicates are ignored). Returns the ordering as a list of variables, first eliminated first.

#include <vector>

namespace semslam {

std::vector<int> constrainedOrdering(const std::vector<std::vector<int>>& neighbours, const std::vector<bool>& last);

}  // namespace semslam
