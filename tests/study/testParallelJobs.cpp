// runParallelJobs, the studies' one thread pool: every index once, results independent of the thread count,
// progress counted to the end without overlapping calls, the first failure rethrown.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "semslam/study/ParallelJobs.h"

namespace semslam {
namespace {

std::vector<long> squares(int threads) {
  std::vector<long> out(200, -1);
  runParallelJobs(out.size(), threads, [&](std::size_t i) { out[i] = static_cast<long>(i * i); });
  return out;
}

TEST(ParallelJobs, EveryIndexRunsOnceAndTheResultsDoNotDependOnTheThreadCount) {
  const std::vector<long> one = squares(1);
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], static_cast<long>(i * i));
  EXPECT_EQ(squares(3), one);
  EXPECT_EQ(squares(0), one);  // fewer than one thread counts as one
  std::atomic<int> calls{0};
  runParallelJobs(0, 4, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelJobs, ProgressCountsEveryJobOneCallAtATime) {
  std::vector<int> seen;
  std::atomic<int> inside{0};
  bool overlapped = false;
  runParallelJobs(
      50, 4, [](std::size_t) {},
      [&](int done, int total) {
        if (++inside > 1) overlapped = true;
        EXPECT_EQ(total, 50);
        seen.push_back(done);
        --inside;
      });
  ASSERT_EQ(seen.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(seen[i], i + 1);
  EXPECT_FALSE(overlapped);
}

TEST(ParallelJobs, TheFirstFailureStopsTheHandOutAndIsRethrown) {
  // Every other job takes 2 ms, so all 1000 would take a second; job 3 fails at once, and jobs not yet handed out
  // by then never start (jobs already running finish).
  std::atomic<int> ran{0};
  EXPECT_THROW(runParallelJobs(1000, 2,
                               [&](std::size_t i) {
                                 ++ran;
                                 if (i == 3) throw std::runtime_error("job 3 failed");
                                 std::this_thread::sleep_for(std::chrono::milliseconds(2));
                               }),
               std::runtime_error);
  EXPECT_LT(ran.load(), 1000);
}

}  // namespace
}  // namespace semslam
