// Gauss-Newton and Levenberg-Marquardt against closed forms and against each other.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include "SmallProblems.h"
#include "semslam/solve/NormalEquations.h"
#include "semslam/solve/Optimizer.h"

using namespace semslam;

namespace {

/// A linear least-squares problem on points: priors and relative measurements with full covariances.
test::Problem linearPointProblem() {
  test::Problem problem;
  Matrix covariance(2, 2);
  covariance << 0.3, 0.1, 0.1, 0.2;
  problem.graph.emplace<PriorFactor<Point2>>(0, Point2(1.0, 2.0), NoiseModel::fromCovariance(covariance));
  problem.graph.emplace<BetweenFactor<Point2>>(0, 1, Point2(1.0, 0.5), NoiseModel::fromSigmas(Vector2(0.1, 0.2)));
  problem.graph.emplace<BetweenFactor<Point2>>(1, 2, Point2(0.0, 1.5), NoiseModel::isotropic(2, 0.3));
  problem.graph.emplace<BetweenFactor<Point2>>(0, 2, Point2(1.2, 1.8), NoiseModel::fromCovariance(covariance));
  problem.graph.emplace<PriorFactor<Point2>>(2, Point2(2.5, 4.0), NoiseModel::isotropic(2, 1.0));
  for (Key key : {0, 1, 2}) problem.initial.insert(key, Point2(10.0 * key, -3.0));
  return problem;
}

}  // namespace

TEST(Optimizer, GaussNewtonSolvesALinearProblemInOneStepExactly) {
  const test::Problem problem = linearPointProblem();
  // Closed form: with r(x) = A x − b linear, the minimiser is x* = (AᵀA)⁻¹Aᵀb = x0 − H⁻¹ g at any x0.
  NormalEquations system(problem.graph, problem.initial);
  system.assemble(problem.initial);
  const Matrix H = Matrix(Matrix(system.hessian()).selfadjointView<Eigen::Upper>());
  const Vector step = -H.ldlt().solve(system.gradient());

  const OptimizationResult result = optimize(problem.graph, problem.initial);
  for (Key key : {0, 1, 2}) {
    const Point2 expected = problem.initial.at<Point2>(key) + step.segment<2>(system.offset(key));
    EXPECT_LE((result.values.at<Point2>(key) - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.iterations, 2);
  // At the minimum the residual is orthogonal to the columns of A: the gradient vanishes.
  system.assemble(result.values);
  EXPECT_LE(system.gradient().cwiseAbs().maxCoeff(), 1e-10);
}

TEST(Optimizer, GaussNewtonAndLevenbergMarquardtAgree) {
  const test::Problem problem = test::planarSlamProblem(20, 6, 9);
  const OptimizationResult gn = optimize(problem.graph, problem.initial);
  OptimizerParams params;
  params.solver = SolverType::LevenbergMarquardt;
  const OptimizationResult lm = optimize(problem.graph, problem.initial, params);
  ASSERT_TRUE(gn.converged) << gn.stopReason;
  ASSERT_TRUE(lm.converged) << lm.stopReason;
  EXPECT_NEAR(gn.finalChi2, lm.finalChi2, 1e-9 * gn.finalChi2);
  EXPECT_LT(gn.finalChi2, gn.initialChi2);
  for (const auto& [key, value] : gn.values) {
    const Vector difference = std::visit(
        [&](const auto& v) -> Vector {
          using T = std::decay_t<decltype(v)>;
          return Manifold<T>::local(v, lm.values.at<T>(key));
        },
        value);
    EXPECT_LE(difference.cwiseAbs().maxCoeff(), 1e-6) << keyToString(key);
  }
  EXPECT_LE(gn.finalGradientNorm, 1e-6 * gn.initialGradientNorm);
}

TEST(Optimizer, LevenbergMarquardtRecoversFromAFarStart) {
  // A start so far off that full Gauss-Newton steps overshoot; the trust region must still find the optimum
  // reached from a good start.
  test::Problem problem = test::planarSlamProblem(16, 5, 4);
  const OptimizationResult reference = optimize(problem.graph, problem.initial);
  Values far;
  for (const auto& [key, value] : problem.initial) {
    if (const SE2* pose = std::get_if<SE2>(&value)) {
      far.insert(key, SE2(pose->x(), pose->y(), pose->theta() + 1.2));
    } else {
      far.insert(key, value);
    }
  }
  OptimizerParams params;
  params.solver = SolverType::LevenbergMarquardt;
  params.maxIterations = 500;
  const OptimizationResult lm = optimize(problem.graph, far, params);
  EXPECT_TRUE(lm.converged) << lm.stopReason;
  EXPECT_NEAR(lm.finalChi2, reference.finalChi2, 1e-6 * reference.finalChi2);
}

TEST(Optimizer, UnconstrainedGaugeIsReported) {
  test::Problem problem = test::planarSlamProblem();
  FactorGraph withoutPrior;
  for (std::size_t i = 1; i < problem.graph.size(); ++i) withoutPrior.add(problem.graph[i]);
  EXPECT_THROW(optimize(withoutPrior, problem.initial), std::runtime_error);
}

TEST(Optimizer, IsDeterministic) {
  const test::Problem problem = test::planarSlamProblem(30, 8, 5);
  const OptimizationResult a = optimize(problem.graph, problem.initial);
  const OptimizationResult b = optimize(problem.graph, problem.initial);
  EXPECT_EQ(a.finalChi2, b.finalChi2);
  for (const auto& [key, value] : a.values) {
    if (const SE2* pose = std::get_if<SE2>(&value)) {
      EXPECT_EQ(pose->x(), b.values.at<SE2>(key).x());
      EXPECT_EQ(pose->theta(), b.values.at<SE2>(key).theta());
    }
  }
}

TEST(Optimizer, AChi2DecreaseToleranceStopsWithinItOfTheOptimum) {
  // Rule 2's absolute form: Gauss-Newton converges quadratically near the optimum, so once a step lowers chi2 by
  // less than the tolerance, what is left is far below it; the run needs fewer steps than the 1e-10 relative rule.
  const test::Problem problem = test::planarSlamProblem(20, 6, 9);
  const OptimizationResult reference = optimize(problem.graph, problem.initial);
  ASSERT_TRUE(reference.converged) << reference.stopReason;
  OptimizerParams params;
  params.chi2DecreaseTolerance = 1e-3;
  const OptimizationResult coarse = optimize(problem.graph, problem.initial, params);
  EXPECT_TRUE(coarse.converged);
  EXPECT_EQ(coarse.stopReason, "decrease of chi2 below its absolute tolerance");
  EXPECT_LT(coarse.iterations, reference.iterations);
  EXPECT_GE(coarse.finalChi2, reference.finalChi2 - 1e-9 * reference.finalChi2);
  EXPECT_LE(coarse.finalChi2, reference.finalChi2 + params.chi2DecreaseTolerance);
  // Off (0, the default) it changes nothing.
  params.chi2DecreaseTolerance = 0.0;
  EXPECT_EQ(optimize(problem.graph, problem.initial, params).finalChi2, reference.finalChi2);
}
