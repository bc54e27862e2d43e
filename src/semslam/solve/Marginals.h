#pragma once
// Marginals: Gaussian marginal covariances of a factor graph's variables at a linearization point X.
//
// The Laplace approximation of the posterior at X has information H = JᵀJ (NormalEquations), so the joint
// covariance of a set S of variables is the S×S block of H⁻¹. It is computed from the sparse Cholesky factor
// P H Pᵀ = L Lᵀ by solving H Y = E_S for the |S| unit columns of S (two sparse triangular solves per column) and
// keeping the rows of S: cost O(|S| · nnz(L)), never a dense inverse of H.

#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"
#include "semslam/solve/JointMarginal.h"
#include "semslam/solve/NormalEquations.h"
#include "semslam/solve/SparseCholesky.h"

namespace semslam {

class Marginals {
 public:
  /// Linearizes and factors the graph at `linearizationPoint`; throws std::runtime_error if H is not positive
  /// definite there.
  Marginals(const FactorGraph& graph, const Values& linearizationPoint);

  /// Covariance of one variable's tangent at the linearization point.
  Matrix marginalCovariance(Key key) const;
  /// Joint covariance of `keys`, in that order (a key may not repeat).
  JointMarginal jointMarginal(const std::vector<Key>& keys) const;
  /// H⁻¹ Jᵀ v for one vector v_f per factor of its whitened error's dimension, in graph order (J: the whitened
  /// Jacobians at the linearization point). With v ~ N(0, I) it is an exact draw from N(0, H⁻¹), the posterior's
  /// tangent offset (models/PosteriorSampler.h draws v).
  Vector posteriorOffset(const std::vector<Vector>& perFactor) const;
  /// values ⊕ delta over the system's variables, in its layout (NormalEquations::retract).
  Values retract(const Values& values, const Vector& delta) const { return system_.retract(values, delta); }
  /// Heap bytes held: the linearized system and its Cholesky factor.
  std::size_t memoryBytes() const { return system_.memoryBytes() + cholesky_.memoryBytes(); }

 private:
  NormalEquations system_;
  SparseCholesky cholesky_;
};

}  // namespace semslam
