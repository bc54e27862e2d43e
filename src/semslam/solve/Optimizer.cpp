#include "semslam/solve/Optimizer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "semslam/solve/NormalEquations.h"
#include "semslam/solve/SparseCholesky.h"
#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam {

namespace {

double maxNorm(const Vector& v) { return v.size() == 0 ? 0.0 : v.cwiseAbs().maxCoeff(); }

void logIteration(const OptimizerParams& params, int iteration, double chi2, double gradient, double lambda) {
  if (!params.verbose) return;
  std::fprintf(stderr, "iter %3d  chi2 %.10g  |g|inf %.3e", iteration, chi2, gradient);
  if (params.solver == SolverType::LevenbergMarquardt) std::fprintf(stderr, "  lambda %.3e", lambda);
  std::fprintf(stderr, "\n");
}

/// Rules 2 and 3 of the header, after an accepted step; sets the reason and returns true to stop.
bool convergedAfterStep(const OptimizerParams& params, double oldChi2, double newChi2, const Vector& step,
                        OptimizationResult& result) {
  if (oldChi2 - newChi2 <= params.relativeDecreaseTolerance * oldChi2) {
    result.stopReason = "relative decrease of chi2 below tolerance";
    result.converged = true;
  } else if (params.chi2DecreaseTolerance > 0.0 && oldChi2 - newChi2 <= params.chi2DecreaseTolerance) {
    result.stopReason = "decrease of chi2 below its absolute tolerance";
    result.converged = true;
  } else if (maxNorm(step) <= params.stepTolerance) {
    result.stopReason = "step below tolerance";
    result.converged = true;
  }
  return result.converged;
}

bool gradientConverged(const OptimizerParams& params, double gradient, OptimizationResult& result) {
  if (gradient <= params.gradientTolerance * result.initialGradientNorm || gradient == 0.0) {
    result.stopReason = "gradient below tolerance";
    result.converged = true;
  }
  return result.converged;
}

void gaussNewton(const FactorGraph& graph, NormalEquations& system, SparseCholesky& cholesky,
                 const OptimizerParams& params, OptimizationResult& result) {
  Values& x = result.values;
  double chi2 = result.initialChi2;
  double gradient = result.initialGradientNorm;
  while (true) {
    logIteration(params, result.iterations, chi2, gradient, 0.0);
    if (gradientConverged(params, gradient, result)) break;
    if (result.iterations >= params.maxIterations) {
      result.stopReason = "maximum number of iterations";
      break;
    }
    // Not positive definite: some variable is not fixed by the factors; say which, and what would fix it.
    if (!cholesky.factorize(system.hessian())) throwUnconstrained(graph, x);
    const Vector step = cholesky.solve(Vector(-system.gradient()));
    ++result.iterations;
    Values candidate = system.retract(x, step);
    const double candidateChi2 = system.assemble(candidate);
    if (!(candidateChi2 <= chi2)) {  // also catches NaN
      result.stopReason = "a Gauss-Newton step increased chi2; kept the previous point";
      system.assemble(x);  // leave the system linearized at the result
      break;
    }
    const double oldChi2 = chi2;
    x = std::move(candidate);
    chi2 = candidateChi2;
    gradient = maxNorm(system.gradient());
    if (convergedAfterStep(params, oldChi2, chi2, step, result)) break;
  }
  result.finalChi2 = chi2;
  result.finalGradientNorm = gradient;
}

void levenbergMarquardt(const FactorGraph& graph, NormalEquations& system, SparseCholesky& cholesky,
                        const OptimizerParams& params, OptimizationResult& result) {
  Values& x = result.values;
  double chi2 = result.initialChi2;
  double gradient = result.initialGradientNorm;
  double lambda = params.initialLambda;
  double nu = 2.0;
  NormalEquations::SparseMatrix damped = system.hessian();
  while (true) {
    logIteration(params, result.iterations, chi2, gradient, lambda);
    if (gradientConverged(params, gradient, result)) break;
    if (result.iterations >= params.maxIterations) {
      result.stopReason = "maximum number of iterations";
      break;
    }
    if (lambda > params.maxLambda) {
      result.stopReason = "damping exceeded its maximum: no step decreases chi2";
      break;
    }
    // (H + λ D) δ = −g with D = diag(H), clamped as Ceres clamps it.
    const NormalEquations::SparseMatrix& hessian = system.hessian();
    std::copy(hessian.valuePtr(), hessian.valuePtr() + hessian.nonZeros(), damped.valuePtr());
    for (int position : system.diagonalPositions()) {
      damped.valuePtr()[position] += lambda * std::clamp(hessian.valuePtr()[position], 1e-6, 1e32);
    }
    ++result.iterations;
    if (!cholesky.factorize(damped)) {
      lambda *= nu;
      nu *= 2.0;
      continue;
    }
    const Vector step = cholesky.solve(Vector(-system.gradient()));
    // Predicted decrease of F = ½ chi2 by the quadratic model.
    const double predicted =
        -system.gradient().dot(step) - 0.5 * step.dot(hessian.selfadjointView<Eigen::Upper>() * step);
    Values candidate = system.retract(x, step);
    const double candidateChi2 = graph.chi2(candidate);
    const double gainRatio = 0.5 * (chi2 - candidateChi2) / predicted;
    if (std::isfinite(candidateChi2) && predicted > 0.0 && gainRatio > 0.0) {
      const double oldChi2 = chi2;
      x = std::move(candidate);
      chi2 = system.assemble(x);
      gradient = maxNorm(system.gradient());
      lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gainRatio - 1.0, 3));
      nu = 2.0;
      if (convergedAfterStep(params, oldChi2, chi2, step, result)) break;
    } else {
      lambda *= nu;
      nu *= 2.0;
    }
  }
  result.finalChi2 = chi2;
  result.finalGradientNorm = gradient;
}

}  // namespace

OptimizationResult optimize(const FactorGraph& graph, const Values& initial, const OptimizerParams& params) {
  OptimizationResult result;
  result.values = initial;
  NormalEquations system(graph, initial);
  result.initialChi2 = system.assemble(initial);
  result.initialGradientNorm = maxNorm(system.gradient());
  if (!std::isfinite(result.initialChi2)) throw std::runtime_error("chi2 at the initial values is not finite");
  SparseCholesky cholesky;
  cholesky.analyze(system.hessian());
  if (params.solver == SolverType::GaussNewton) {
    gaussNewton(graph, system, cholesky, params, result);
  } else {
    levenbergMarquardt(graph, system, cholesky, params, result);
  }
  return result;
}

}  // namespace semslam
