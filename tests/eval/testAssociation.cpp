// Timestamp association as evo's sync.associate_trajectories, on hand-made stamps.

#include <gtest/gtest.h>

#include <random>

#include "semslam/eval/Association.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

using Indices = std::vector<std::size_t>;

/// A trajectory whose pose i sits at x = i, so that associated poses can be recognised.
Trajectory trajectoryAt(const std::vector<double>& stamps) {
  std::vector<SE3> poses;
  for (std::size_t i = 0; i < stamps.size(); ++i) poses.emplace_back(SO3(), Point3(static_cast<double>(i), 0, 0));
  return Trajectory(stamps, poses);
}

/// numpy's argmin, by brute force: the reference for the fast path.
TimeMatches bruteForce(const std::vector<double>& s1, const std::vector<double>& s2, double maxDiff, double offset) {
  TimeMatches m;
  for (std::size_t i = 0; i < s1.size(); ++i) {
    std::size_t best = 0;
    for (std::size_t j = 1; j < s2.size(); ++j) {
      if (std::abs((s2[j] + offset) - s1[i]) < std::abs((s2[best] + offset) - s1[i])) best = j;
    }
    if (std::abs((s2[best] + offset) - s1[i]) <= maxDiff) {
      m.first.push_back(i);
      m.second.push_back(best);
    }
  }
  return m;
}

TEST(Association, MatchesNearestStampsWithinMaxDiff) {
  const Trajectory ref = trajectoryAt({0.0, 0.1, 0.2, 0.3, 0.4});
  const Trajectory est = trajectoryAt({0.005, 0.103, 0.25, 0.399});  // 0.25 is 0.05 from both neighbours
  const AssociatedTrajectories a = associateTrajectories(ref, est, 0.01);
  EXPECT_EQ(a.estimateIndices, (Indices{0, 1, 3}));
  EXPECT_EQ(a.referenceIndices, (Indices{0, 1, 4}));
  ASSERT_EQ(a.reference.size(), 3u);
  ASSERT_EQ(a.estimate.size(), 3u);
  EXPECT_EQ(a.reference.position(2).x(), 4.0);
  EXPECT_EQ(a.estimate.position(2).x(), 3.0);
  EXPECT_DOUBLE_EQ(a.estimate.timestamp(2), 0.399);
}

TEST(Association, MaxDiffBoundIsInclusiveAndTiesTakeTheFirstStamp) {
  const std::vector<double> s1{1.5};
  const TimeMatches m = matchingTimeIndices(s1, {1.0, 2.0}, 0.5);  // |1.0 - 1.5| = |2.0 - 1.5| = 0.5
  EXPECT_EQ(m.first, (Indices{0}));
  EXPECT_EQ(m.second, (Indices{0}));
  EXPECT_TRUE(matchingTimeIndices(s1, {1.0, 2.0}, 0.49).first.empty());
}

TEST(Association, DuplicateStampsTakeTheFirst) {
  const TimeMatches m = matchingTimeIndices({2.0, 3.0}, {1.0, 2.0, 2.0, 2.0, 3.0, 3.0}, 0.01);
  EXPECT_EQ(m.second, (Indices{1, 4}));
}

TEST(Association, ShorterTrajectoryDrivesTheMatchingAndMayReuseStamps) {
  // The reference is shorter here, so each reference stamp finds its nearest estimate stamp.
  const Trajectory ref = trajectoryAt({1.0, 1.004});
  const Trajectory est = trajectoryAt({0.9, 1.002, 1.1});
  const AssociatedTrajectories a = associateTrajectories(ref, est, 0.01);
  EXPECT_EQ(a.referenceIndices, (Indices{0, 1}));
  EXPECT_EQ(a.estimateIndices, (Indices{1, 1}));  // evo keeps both, reusing the estimate pose
}

TEST(Association, OffsetIsAddedToTheEstimate) {
  const Trajectory ref = trajectoryAt({10.0, 11.0, 12.0});
  const Trajectory est = trajectoryAt({0.0, 1.0, 2.0});
  EXPECT_THROW(associateTrajectories(ref, est, 0.01, 0.0), InputError);
  const AssociatedTrajectories a = associateTrajectories(ref, est, 0.01, 10.0);
  EXPECT_EQ(a.referenceIndices, (Indices{0, 1, 2}));
  EXPECT_EQ(a.estimateIndices, (Indices{0, 1, 2}));
  // Same with the estimate longer (the other branch of evo's code).
  const Trajectory longEst = trajectoryAt({0.0, 0.5, 1.0, 1.5, 2.0});
  const AssociatedTrajectories b = associateTrajectories(ref, longEst, 0.01, 10.0);
  EXPECT_EQ(b.referenceIndices, (Indices{0, 1, 2}));
  EXPECT_EQ(b.estimateIndices, (Indices{0, 2, 4}));
}

TEST(Association, SortedFastPathAgreesWithBruteForce) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> jitter(-0.004, 0.004);
  std::uniform_int_distribution<int> dup(0, 9);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> s1, s2;
    for (int i = 0; i < 300; ++i) s1.push_back(100.0 + 0.033 * i + jitter(rng));
    double t = 99.5;
    for (int j = 0; j < 1000; ++j) {
      if (dup(rng) != 0) t += 0.01;  // some duplicates
      s2.push_back(t);
    }
    const double offset = 0.001 * trial;
    const TimeMatches fast = matchingTimeIndices(s1, s2, 0.004, offset);
    const TimeMatches slow = bruteForce(s1, s2, 0.004, offset);
    EXPECT_EQ(fast.first, slow.first);
    EXPECT_EQ(fast.second, slow.second);
  }
}

TEST(Association, UnsortedStampsAreSearchedExhaustively) {
  const TimeMatches m = matchingTimeIndices({1.0, 2.0, 3.0}, {3.001, 0.999, 2.0, 5.0}, 0.01);
  EXPECT_EQ(m.first, (Indices{0, 1, 2}));
  EXPECT_EQ(m.second, (Indices{1, 2, 0}));
}

TEST(Association, TrajectoriesWithoutTimestampsPairByIndex) {
  std::vector<SE3> poses(4);
  const Trajectory untimed = Trajectory::withoutTimestamps(poses);
  const Trajectory timed = trajectoryAt({5.0, 6.0, 7.0, 8.0});
  const AssociatedTrajectories a = associateTrajectories(untimed, timed);
  EXPECT_EQ(a.referenceIndices, (Indices{0, 1, 2, 3}));
  EXPECT_EQ(a.estimateIndices, (Indices{0, 1, 2, 3}));
  EXPECT_THROW(associateTrajectories(untimed, trajectoryAt({1.0, 2.0})), InputError);
}

TEST(Association, BadParametersAndNoMatchThrow) {
  const Trajectory ref = trajectoryAt({0.0, 1.0});
  EXPECT_THROW(associateTrajectories(ref, ref, -0.1), InputError);
  EXPECT_THROW(associateTrajectories(ref, ref, std::nan("")), InputError);
  EXPECT_THROW(associateTrajectories(ref, trajectoryAt({0.5}), 0.01), InputError);
  EXPECT_THROW(associateTrajectories(ref, Trajectory()), InputError);
}

}  // namespace
}  // namespace semslam
