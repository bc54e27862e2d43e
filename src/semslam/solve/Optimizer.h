#pragma once
// Nonlinear least squares on a factor graph: minimise F(X) = ½ Σ_f chi2_f(X) over the manifold variables.
//
// Gauss-Newton: solve H δ = −g (NormalEquations) and step X ← X ⊕ δ.
// Levenberg-Marquardt: a trust-region method driven by the gain ratio
//     ρ = (F(X) − F(X ⊕ δ)) / (L(0) − L(δ)),   L(0) − L(δ) = −gᵀδ − ½ δᵀHδ,
// for the step of (H + λ D) δ = −g with D = diag(H) (clamped to [1e-6, 1e32] as Ceres does): a step with ρ > 0
// is accepted and λ ← λ · max(1/3, 1 − (2ρ − 1)³), ν ← 2; a rejected step gives λ ← λ ν, ν ← 2ν
// (Nielsen's rule; Madsen, Nielsen and Tingleff, "Methods for non-linear least squares problems", 2004).
//
// Stopping rules (checked in this order after each accepted step; the result is the last accepted point):
//   1. gradient:  ‖g‖∞ ≤ gradientTolerance · ‖g₀‖∞ (g₀ at the initial values), or ‖g‖∞ = 0;
//   2. decrease:  (F_old − F_new) ≤ relativeDecreaseTolerance · F_old, or, when chi2DecreaseTolerance > 0,
//                 chi2_old − chi2_new ≤ chi2DecreaseTolerance (an absolute bound, for a caller that needs chi2 only
//                 to a known precision: the loop-closure branch score, slam/BranchScore.h);
//   3. small step: ‖δ‖∞ ≤ stepTolerance;
//   4. maxIterations linear solves;
//   Gauss-Newton also stops (keeping the previous point) if a step increases F: it has no way to recover, use
//   Levenberg-Marquardt on such problems. Levenberg-Marquardt stops when λ exceeds maxLambda.

#include <string>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"

namespace semslam {

enum class SolverType { GaussNewton, LevenbergMarquardt };

struct OptimizerParams {
  SolverType solver = SolverType::GaussNewton;
  int maxIterations = 100;
  double relativeDecreaseTolerance = 1e-10;
  double chi2DecreaseTolerance = 0.0;  // absolute, in units of chi2; 0 turns the absolute rule off
  double gradientTolerance = 1e-10;
  double stepTolerance = 1e-12;
  double initialLambda = 1e-5;
  double maxLambda = 1e16;
  bool verbose = false;  // one line per iteration on stderr
};

struct OptimizationResult {
  Values values;
  double initialChi2 = 0.0;
  double finalChi2 = 0.0;
  double initialGradientNorm = 0.0;  // ‖g₀‖∞
  double finalGradientNorm = 0.0;    // ‖g‖∞ at the result
  int iterations = 0;                // linear solves
  std::string stopReason;
  bool converged = false;            // stopped by rule 1, 2 or 3
};

/// Minimises the graph's objective from `initial`. Throws std::runtime_error if the information matrix is not
/// positive definite at the initial values (some variable is unconstrained), and std::invalid_argument if a
/// factor names a variable without a value.
OptimizationResult optimize(const FactorGraph& graph, const Values& initial, const OptimizerParams& params = {});

}  // namespace semslam
