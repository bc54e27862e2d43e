// BatchSmoother: incremental use equals one batch solve; removal, replacement and fork behave as specified.

#include <gtest/gtest.h>

#include "SmallProblems.h"
#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/Marginals.h"

using namespace semslam;

namespace {

/// Feeds the problem's factors to a smoother pose by pose, as an online front end would.
std::unique_ptr<BatchSmoother> feedIncrementally(const test::Problem& problem) {
  auto smoother = std::make_unique<BatchSmoother>();
  Values pending = problem.initial;
  std::vector<FactorPtr> remaining(problem.graph.begin(), problem.graph.end());
  while (!remaining.empty()) {
    // Take the next pose and every factor whose variables are then all known.
    Values newValues;
    const Key next = [&] {
      for (const auto& [key, value] : pending) {
        if (Symbol(key).tag() == 'x') return key;
      }
      return pending.begin()->first;
    }();
    newValues.insert(next, pending.value(next));
    pending.erase(next);
    FactorGraph newFactors;
    std::vector<FactorPtr> later;
    for (const auto& factor : remaining) {
      bool ready = true;
      for (Key key : factor->keys()) {
        if (!smoother->estimate().exists(key) && !newValues.exists(key)) {
          if (Symbol(key).tag() == 'l' && pending.exists(key)) {
            newValues.insert(key, pending.value(key));  // a landmark enters with its first observation
            pending.erase(key);
          } else {
            ready = false;
          }
        }
      }
      (ready ? newFactors.add(factor) : later.push_back(factor));
    }
    remaining = later;
    smoother->update(newFactors, newValues);
  }
  return smoother;
}

}  // namespace

TEST(BatchSmoother, IncrementalUpdatesEqualOneBatchSolve) {
  const test::Problem problem = test::planarSlamProblem(12, 5, 21);
  const auto smoother = feedIncrementally(problem);
  const OptimizationResult batch = optimize(problem.graph, problem.initial);
  EXPECT_NEAR(smoother->factors().chi2(smoother->estimate()), batch.finalChi2, 1e-8 * batch.finalChi2);
  for (const auto& [key, value] : batch.values) {
    if (const SE2* pose = std::get_if<SE2>(&value)) {
      EXPECT_LE(SE2::Log(pose->between(smoother->estimate<SE2>(key))).norm(), 1e-6) << keyToString(key);
    }
  }
  const Marginals marginals(problem.graph, smoother->estimate());
  EXPECT_TRUE(smoother->marginalCovariance(poseKey(11)).isApprox(marginals.marginalCovariance(poseKey(11)), 1e-9));
}

TEST(BatchSmoother, RemoveAndReplaceFactors) {
  const test::Problem problem = test::planarSlamProblem(8, 3, 2);
  BatchSmoother smoother;
  const std::vector<FactorIndex> indices = smoother.update(problem.graph, problem.initial);
  ASSERT_EQ(indices.size(), problem.graph.size());

  // Removing the last landmark observation equals solving without it.
  const FactorIndex removed = indices.back();
  smoother.update({}, {}, {removed});
  FactorGraph without;
  for (std::size_t i = 0; i + 1 < problem.graph.size(); ++i) without.add(problem.graph[i]);
  const OptimizationResult expected = optimize(without, problem.initial);
  EXPECT_NEAR(smoother.factors().chi2(smoother.estimate()), expected.finalChi2, 1e-8 * expected.finalChi2);
  EXPECT_EQ(smoother.factors().size(), without.size());
  EXPECT_THROW(smoother.update({}, {}, {removed}), std::invalid_argument);

  // Replacing the prior by a different one moves the solution to the new prior's mean.
  const SE2 moved(1.0, -2.0, 0.4);
  smoother.replaceFactor(indices.front(), std::make_shared<PriorFactor<SE2>>(
                                               poseKey(0), moved, NoiseModel::isotropic(3, 1e-4)));
  smoother.update();
  EXPECT_LE(SE2::Log(moved.between(smoother.estimate<SE2>(poseKey(0)))).norm(), 1e-3);
  EXPECT_THROW(smoother.replaceFactor(removed, problem.graph[0]), std::invalid_argument);
}

TEST(BatchSmoother, ForkSharesFactorsAndDivergesIndependently) {
  const test::Problem problem = test::planarSlamProblem(8, 3, 6);
  BatchSmoother original;
  original.update(problem.graph, problem.initial);
  const std::unique_ptr<Smoother> branch = original.fork();
  const FactorGraph a = original.factors(), b = branch->factors();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].get(), b[i].get());  // shared, not copied

  Values newValue;
  newValue.insert(landmarkKey(50), Point2(0.0, 0.0));
  FactorGraph newFactor;
  newFactor.emplace<RelativePointFactor<SE2, Point2>>(poseKey(0), landmarkKey(50), Point2(1.0, 1.0),
                                                      NoiseModel::isotropic(2, 0.1));
  branch->update(newFactor, newValue);
  EXPECT_TRUE(branch->estimate().exists(landmarkKey(50)));
  EXPECT_FALSE(original.estimate().exists(landmarkKey(50)));
  EXPECT_EQ(original.factors().size(), problem.graph.size());
}

TEST(BatchSmoother, RejectsInconsistentUpdates) {
  const test::Problem problem = test::planarSlamProblem(6, 2, 1);
  BatchSmoother smoother;
  smoother.update(problem.graph, problem.initial);
  Values duplicate;
  duplicate.insert(poseKey(0), SE2());
  EXPECT_THROW(smoother.update({}, duplicate), std::invalid_argument);
  FactorGraph dangling;
  dangling.emplace<PriorFactor<SE2>>(poseKey(77), SE2(), NoiseModel::isotropic(3, 1.0));
  EXPECT_THROW(smoother.update(dangling, {}), std::invalid_argument);
}
