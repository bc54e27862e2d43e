#include "semslam/solve/Marginals.h"

#include <algorithm>
#include <stdexcept>

#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam {

namespace {

/// `graph`, which must have a factor: without one no variable has a marginal (and an empty system has no
/// factorisation to take them from).
const FactorGraph& nonEmpty(const FactorGraph& graph) {
  if (graph.empty()) throw std::invalid_argument("Marginals: the graph has no factors, so no variable has a marginal");
  return graph;
}

}  // namespace

Marginals::Marginals(const FactorGraph& graph, const Values& linearizationPoint)
    : system_(nonEmpty(graph), linearizationPoint) {
  system_.assemble(linearizationPoint);
  cholesky_.analyze(system_.hessian());
  if (!cholesky_.factorize(system_.hessian())) {
    throwUnconstrained(graph, linearizationPoint);
  }
}

Vector Marginals::posteriorOffset(const std::vector<Vector>& perFactor) const {
  return cholesky_.solve(system_.transposedJacobianTimes(perFactor));
}

Matrix Marginals::marginalCovariance(Key key) const { return jointMarginal({key}).covariance(); }

JointMarginal Marginals::jointMarginal(const std::vector<Key>& keys) const {
  std::vector<Key> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    throw std::invalid_argument("jointMarginal: a key is repeated");
  }
  std::vector<int> dimensions;
  std::vector<int> columns;  // scalar columns of H for the requested keys, in request order
  for (Key key : keys) {
    const int offset = system_.offset(key);
    const int d = system_.dimension(key);
    dimensions.push_back(d);
    for (int i = 0; i < d; ++i) columns.push_back(offset + i);
  }
  const int k = static_cast<int>(columns.size());
  if (k == 0) return JointMarginal({}, {}, Matrix(0, 0));  // no key asked for: the empty marginal, as the Bayes tree
  Matrix unit = Matrix::Zero(system_.dimension(), k);
  for (int j = 0; j < k; ++j) unit(columns[j], j) = 1.0;
  const Matrix solved = cholesky_.solve(unit);  // H⁻¹ E_S
  Matrix covariance(k, k);
  for (int i = 0; i < k; ++i) covariance.row(i) = solved.row(columns[i]);
  covariance = 0.5 * (covariance + covariance.transpose());  // exact symmetry
  return JointMarginal(keys, std::move(dimensions), std::move(covariance));
}

}  // namespace semslam
