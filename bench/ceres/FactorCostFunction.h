#pragma once
// FactorCostFunction: one semslam factor as a ceres::CostFunction.
//
// Evaluate decodes each parameter block (AmbientCoordinates.h) into a Values view, calls Factor::linearize, and
// hands Ceres the whitened error as the residual and our tangent-space Jacobians ∂r/∂δ_k, row-major, in the
// place of the ambient Jacobians (ValueManifold.h explains why that is exact). Ceres's cost ½‖r‖² is then our
// ½ chi2 for every Gaussian factor. (Under a robust kernel our r already carries the IRLS weight, so Ceres
// would see a different cost: the pose graphs benchmarked here have no kernels.)
//
// The view is a Values of just this factor's variables, built per call (thread-safe, since Ceres evaluates in
// parallel with num_threads > 1). Measured on manhattan, that costs 217 ns per SE2 between factor against
// 380 ns for one thread-local Values holding every variable and overwritten in place: two map nodes allocated
// per call are cheaper than two lookups in a 3500-entry std::map.
//
// Factor has no residual-only entry point, so a call without Jacobians still linearizes (and drops them).

#include <ceres/cost_function.h>

#include <vector>

#include "AmbientCoordinates.h"
#include "semslam/graph/Factor.h"

namespace semslam::bench {

class FactorCostFunction final : public ceres::CostFunction {
 public:
  /// `kinds[k]` is the kind of the value of factor->keys()[k].
  FactorCostFunction(FactorPtr factor, std::vector<ValueKind> kinds);

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  FactorPtr factor_;
  std::vector<ValueKind> kinds_;
};

}  // namespace semslam::bench
