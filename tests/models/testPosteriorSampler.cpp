// PosteriorSampler: draws X̂ ⊕ s H⁻¹ Jᵀ v, v ~ N(0, I), whose tangent offsets have the covariance s² H⁻¹ (the joint
// posterior at the optimum), mean 0, and come out the same for the same seed.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "semslam/geometry/Manifold.h"
#include "semslam/models/PosteriorSampler.h"
#include "semslam/solve/NormalEquations.h"
#include "semslam/solve/Optimizer.h"
#include "semslam/solve/UnconstrainedSystem.h"
#include "solve/SmallProblems.h"

using namespace semslam;

namespace {

/// The tangent offset of `drawn` from `optimum`, stacked in NormalEquations' key order.
Vector offsetOf(const Values& drawn, const Values& optimum, const NormalEquations& system) {
  Vector offset(system.dimension());
  for (Key key : system.keys()) {
    const Value& at = optimum.value(key);
    const Value& to = drawn.value(key);
    offset.segment(system.offset(key), system.dimension(key)) = std::visit(
        [&](const auto& x) -> Vector {
          using T = std::decay_t<decltype(x)>;
          return Manifold<T>::local(x, std::get<T>(to));
        },
        at);
  }
  return offset;
}

}  // namespace

TEST(PosteriorSampler, DrawsHaveTheJointPosteriorCovarianceAndMeanZero) {
  const test::Problem problem = test::planarSlamProblem(6, 3, 5);
  const Values optimum = optimize(problem.graph, problem.initial).values;
  NormalEquations system(problem.graph, optimum);
  system.assemble(optimum);
  const Matrix covariance = Matrix(Matrix(system.hessian()).selfadjointView<Eigen::Upper>()).inverse();

  const PosteriorSampler sampler(problem.graph, optimum);
  std::mt19937 rng(11);
  const int draws = 20000;
  const double scale = 2.0;
  const int n = system.dimension();
  Vector sum = Vector::Zero(n);
  Matrix products = Matrix::Zero(n, n);
  for (int i = 0; i < draws; ++i) {
    const Vector offset = offsetOf(sampler.draw(scale, rng), optimum, system);
    sum += offset;
    products += offset * offset.transpose();
  }
  const Vector mean = sum / draws;
  const Matrix sampleCovariance = products / draws - mean * mean.transpose();
  const Matrix expected = scale * scale * covariance;
  // Monte Carlo standard errors: σ_i / √N for a mean, √((Σ_ii Σ_jj + Σ_ij²) / N) for a covariance entry. The
  // offsets of consecutive poses are correlated (a joint draw), which independent draws from the marginals lack.
  for (int i = 0; i < n; ++i) {
    EXPECT_LT(std::abs(mean(i)), 5.0 * std::sqrt(expected(i, i) / draws)) << "entry " << i;
    for (int j = 0; j < n; ++j) {
      const double error = std::sqrt((expected(i, i) * expected(j, j) + expected(i, j) * expected(i, j)) / draws);
      EXPECT_LT(std::abs(sampleCovariance(i, j) - expected(i, j)), 5.0 * error) << "entry " << i << ", " << j;
    }
  }
  // The correlations are there to be matched: consecutive headings are far from independent (a draw from each
  // pose's marginal would make them so, and fail the check above).
  const int heading4 = system.offset(poseKey(4)) + 2, heading5 = system.offset(poseKey(5)) + 2;
  EXPECT_GT(expected(heading4, heading5) / std::sqrt(expected(heading4, heading4) * expected(heading5, heading5)), 0.5);
}

TEST(PosteriorSampler, SameSeedSameDrawAndScaleZeroIsTheOptimum) {
  const test::Problem problem = test::planarSlamProblem(5, 2, 3);
  const Values optimum = optimize(problem.graph, problem.initial).values;
  const PosteriorSampler sampler(problem.graph, optimum);
  NormalEquations system(problem.graph, optimum);
  std::mt19937 a(4), b(4);
  const Vector first = offsetOf(sampler.draw(1.0, a), optimum, system);
  const Vector second = offsetOf(sampler.draw(1.0, b), optimum, system);
  EXPECT_GT(first.norm(), 0.0);
  EXPECT_EQ(first, second);  // bit for bit
  std::mt19937 c(4);
  EXPECT_LT(offsetOf(sampler.draw(0.0, c), optimum, system).norm(), 1e-12);
  EXPECT_THROW(sampler.draw(-1.0, c), std::invalid_argument);
  EXPECT_THROW(sampler.draw(std::nan(""), c), std::invalid_argument);
}

TEST(PosteriorSampler, AnEmptyOrUnconstrainedGraphIsRefused) {
  EXPECT_THROW(PosteriorSampler(FactorGraph(), Values()), std::invalid_argument);
  test::Problem problem = test::planarSlamProblem(4, 2, 3);
  FactorGraph withoutPrior;
  for (std::size_t f = 1; f < problem.graph.size(); ++f) withoutPrior.add(problem.graph[f]);  // factor 0: the prior
  const Values optimum = optimize(problem.graph, problem.initial).values;
  EXPECT_THROW(PosteriorSampler(withoutPrior, optimum), UnconstrainedSystemError);
}
