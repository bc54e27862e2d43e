// RPE pose pairs as evo's filter_pairs_by_index / filter_pairs_by_path, on hand-made trajectories.

#include <gtest/gtest.h>

#include "semslam/eval/PairSelection.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

using Pairs = std::vector<PosePair>;

/// Poses along x at the given positions (identity rotations).
Trajectory alongX(const std::vector<double>& xs) {
  std::vector<SE3> poses;
  for (const double x : xs) poses.emplace_back(SO3(), Point3(x, 0, 0));
  return Trajectory::withoutTimestamps(poses);
}

TEST(PairSelection, FramesConsecutiveAndAllPairs) {
  const Trajectory t = alongX({0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  EXPECT_EQ(selectPosePairs(t, 3, DeltaUnit::Frames), (Pairs{{0, 3}, {3, 6}, {6, 9}}));
  EXPECT_EQ(selectPosePairs(t, 4, DeltaUnit::Frames), (Pairs{{0, 4}, {4, 8}}));
  EXPECT_EQ(selectPosePairs(t, 1, DeltaUnit::Frames).size(), 9u);
  EXPECT_EQ(selectPosePairs(t, 7, DeltaUnit::Frames, true), (Pairs{{0, 7}, {1, 8}, {2, 9}}));
}

TEST(PairSelection, PathConsecutiveStartsWhereThePathFirstReachesDelta) {
  // 1 m steps: the accumulated path reaches 2.5 m at pose 3 (3 m), then restarts: 6, 9. Pose 0 is not a pair start
  // (evo's filter_pairs_by_path).
  const Trajectory t = alongX({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  EXPECT_EQ(selectPosePairs(t, 2.5, DeltaUnit::Meters), (Pairs{{3, 6}, {6, 9}}));
  // Exactly reaching delta counts (>=): 2 m -> poses 2, 4, 6, 8, 10.
  EXPECT_EQ(selectPosePairs(t, 2.0, DeltaUnit::Meters), (Pairs{{2, 4}, {4, 6}, {6, 8}, {8, 10}}));
  // The path, not the straight-line distance: going back and forth still accumulates.
  const Trajectory zigzag = alongX({0, 1, 0, 1, 0, 1, 0});
  EXPECT_EQ(selectPosePairs(zigzag, 2.0, DeltaUnit::Meters), (Pairs{{2, 4}, {4, 6}}));
}

TEST(PairSelection, PathAllPairsTakesTheClosestPathLengthWithinTolerance) {
  const Trajectory t = alongX({0, 1, 2, 3.1, 4, 5});
  // delta 2, tolerance 10 % = 0.2: from 0 -> 2 (2.0); 1 -> 3.1 (2.1); 2 -> 4 (2.0); 3.1 -> 5 (1.9); 4 -> 5 (1.0, out).
  EXPECT_EQ(selectPosePairs(t, 2.0, DeltaUnit::Meters, true, 0.1), (Pairs{{0, 2}, {1, 3}, {2, 4}, {3, 5}}));
  EXPECT_EQ(selectPosePairs(t, 2.0, DeltaUnit::Meters, true, 0.04), (Pairs{{0, 2}, {2, 4}}));
  // Ties take the first index: from 0, path 1 and 3 are both 1 away from 2 when pose 2 is missing.
  EXPECT_EQ(selectPosePairs(alongX({0, 1, 3}), 2.0, DeltaUnit::Meters, true, 0.5), (Pairs{{0, 1}, {1, 2}}));
}

TEST(PairSelection, InvalidDeltasAndEmptyResultsThrow) {
  const Trajectory t = alongX({0, 1, 2});
  EXPECT_THROW(selectPosePairs(t, 0, DeltaUnit::Frames), InputError);
  EXPECT_THROW(selectPosePairs(t, -1, DeltaUnit::Meters), InputError);
  EXPECT_THROW(selectPosePairs(t, 1.5, DeltaUnit::Frames), InputError);
  EXPECT_THROW(selectPosePairs(t, 3, DeltaUnit::Frames), InputError);   // no pair in 3 poses
  EXPECT_THROW(selectPosePairs(t, 1.5, DeltaUnit::Meters), InputError);  // reached once only
  EXPECT_THROW(selectPosePairs(t, 1.0, DeltaUnit::Meters, true, -0.1), InputError);
  EXPECT_EQ(parseDeltaUnit("m"), DeltaUnit::Meters);
  EXPECT_EQ(parseDeltaUnit("frames"), DeltaUnit::Frames);
  EXPECT_THROW(parseDeltaUnit("deg"), InputError);
}

}  // namespace
}  // namespace semslam

namespace semslam {
namespace {

TEST(PairSelection, AHugeFrameDeltaPairsNothingInsteadOfOverflowing) {
  // eval rpe --delta 1e300 cast the delta to size_t (undefined; it became 0 and the loop never ended).
  const Trajectory t = alongX({0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  for (const double delta : {10.0, 1e19, 1e300}) {
    for (const bool all : {false, true}) {
      try {
        selectPosePairs(t, delta, DeltaUnit::Frames, all, 0.1);
        ADD_FAILURE() << "no error for delta " << delta;
      } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("produced no pose pair"), std::string::npos) << error.what();
      }
    }
  }
  EXPECT_EQ(selectPosePairs(t, 9.0, DeltaUnit::Frames, false, 0.1).size(), 1u);
}

}  // namespace
}  // namespace semslam
