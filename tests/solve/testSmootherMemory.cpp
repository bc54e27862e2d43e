// Smoother::memoryBytes (solve/Smoother.h): the count the hybrid belief's memory bound reads. It is
// deterministic, grows with the graph about linearly on a chain, and counts a batch smoother's cached
// factorization while it is held (gone after the next update).

#include <gtest/gtest.h>

#include "SmallProblems.h"
#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/IncrementalSmoother.h"

using namespace semslam;

namespace {

std::unique_ptr<Smoother> solved(bool incremental, int poses) {
  const test::Problem problem = test::planarSlamProblem(poses, 5, 3);
  std::unique_ptr<Smoother> smoother;
  if (incremental) smoother = std::make_unique<IncrementalSmoother>();
  else smoother = std::make_unique<BatchSmoother>();
  smoother->update(problem.graph, problem.initial);
  return smoother;
}

TEST(SmootherMemory, DeterministicAndGrowingAboutLinearlyWithTheChain) {
  for (bool incremental : {false, true}) {
    const std::size_t small = solved(incremental, 20)->memoryBytes();
    const std::size_t again = solved(incremental, 20)->memoryBytes();
    const std::size_t large = solved(incremental, 80)->memoryBytes();
    EXPECT_EQ(small, again) << (incremental ? "incremental" : "batch");
    EXPECT_GT(small, 20u * sizeof(SE2)) << "at least the poses themselves";
    // Four times the poses: more than twice the bytes, less than eight times (no quadratic term on a chain).
    EXPECT_GT(large, 2 * small) << (incremental ? "incremental" : "batch");
    EXPECT_LT(large, 8 * small) << (incremental ? "incremental" : "batch");
  }
}

TEST(SmootherMemory, ABatchSmootherCountsItsCachedFactorizationWhileItHoldsIt) {
  const test::Problem problem = test::planarSlamProblem(30, 5, 3);
  BatchSmoother smoother;
  smoother.update(problem.graph, problem.initial);
  const std::size_t bare = smoother.memoryBytes();
  smoother.marginalCovariance(poseKey(3));  // factors the system and keeps it for later marginals
  const std::size_t cached = smoother.memoryBytes();
  // The cache holds at least H's nonzeros (a 3x3 block per pose and per pose pair) and a Cholesky factor.
  EXPECT_GT(cached, bare + 30u * 9u * sizeof(double));
  const std::unique_ptr<Smoother> fork = smoother.fork();
  // Shares the cache: counted as its own (an upper bound); only its slot table's spare room may differ.
  EXPECT_GT(fork->memoryBytes(), bare + 30u * 9u * sizeof(double));
  smoother.update();  // re-solves; the cache is for the old estimate and is dropped
  EXPECT_EQ(smoother.memoryBytes(), bare);
}

}  // namespace
