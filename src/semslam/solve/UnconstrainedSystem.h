#pragma once
// Why a least-squares system cannot be solved, in words a user can act on.
//
// The normal equations H δ = −g (H = Σ Jᵢᵀ Jᵢ over the whitened factor Jacobians) have a unique solution only when
// H is positive definite, that is when the factors fix every direction of every variable. When the Cholesky
// factorisation finds a non-positive pivot, describeUnconstrained() looks for the cause, in this order:
//   1. a connected part of the graph (variables joined by factors of two or more variables) with no factor of a
//      single variable in it: nothing holds that part in place (the gauge freedom of relative measurements), so
//      it needs a prior on one of its variables, or a factor joining it to a part that has one;
//   2. a variable whose own factors leave a direction free: its diagonal block Σ Jᵢ,ᵥᵀ Jᵢ,ᵥ of H is singular
//      (smallest eigenvalue ≤ 1e-12 × the largest; e.g. a landmark measured from one place by a sensor that does
//      not observe all of its coordinates);
//   3. a variable that has a value but that no factor names (the batch solvers leave such a variable out of the
//      system, the incremental smoother cannot);
//   otherwise a freedom shared by several variables (no single culprit), described as such.
// Each description names the variables (at most 8, then how many more) and says what would supply the missing
// constraint. The solvers throw UnconstrainedSystemError with it instead of a bare "not positive definite"; the
// commands turn it into an input error naming their file (exit 2).

#include <stdexcept>
#include <string>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"

namespace semslam {

/// The system of `graph` at `values` is not positive definite; what() says which variables and what is missing.
class UnconstrainedSystemError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The first cause found (see above), as a sentence or two starting with "the system cannot be solved: ".
std::string describeUnconstrained(const FactorGraph& graph, const Values& values);

/// Throws UnconstrainedSystemError(describeUnconstrained(graph, values)).
[[noreturn]] void throwUnconstrained(const FactorGraph& graph, const Values& values);

}  // namespace semslam
