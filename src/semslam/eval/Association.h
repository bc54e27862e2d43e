#pragma once
// Timestamp association of two trajectories, as evo's sync.associate_trajectories (evo/core/sync.py, the
// default `nearest_time` method):
//
//   matching_time_indices(s1, s2, max_diff, offset): for each stamp s1[i], in order, the index
//     j = argmin_j |(s2[j] + offset) - s1[i]|   (the FIRST index on ties, as numpy's argmin)
//   is kept, with i, when that smallest difference is <= max_diff. A stamp of s2 may be used more than once.
//
//   associate(ref, est, max_diff = 0.01 s, offset = 0): the trajectory with FEWER poses is the one matched from
//   (when both have the same number, that is the estimate); the offset is added to the estimate's stamps. Both
//   trajectories are reduced to the matched poses, in the order of the shorter one.
//
// Trajectories without timestamps (KITTI files without a time column) cannot be associated by time: evo then
// requires the same number of poses and pairs them by index, and so does this function.

#include <cstddef>
#include <vector>

#include "semslam/models/Trajectory.h"

namespace semslam {

struct TimeMatches {
  std::vector<std::size_t> first;   ///< indices into the first stamp vector
  std::vector<std::size_t> second;  ///< the matching indices into the second one
};

/// evo's matching_time_indices (see above). Linear-time per stamp in general, logarithmic when `stamps2` is sorted.
TimeMatches matchingTimeIndices(const std::vector<double>& stamps1, const std::vector<double>& stamps2,
                                double maxDiff, double offset2 = 0.0);

struct AssociatedTrajectories {
  Trajectory reference;
  Trajectory estimate;
  std::vector<std::size_t> referenceIndices;  ///< where each associated pose came from in the input reference
  std::vector<std::size_t> estimateIndices;   ///< ... and in the input estimate
};

/// Associates by time (or by index when either trajectory has no timestamps). Throws InputError when maxDiff is
/// negative or not finite, when no pair matches, or when index pairing meets different sizes.
AssociatedTrajectories associateTrajectories(const Trajectory& reference, const Trajectory& estimate,
                                             double maxDiff = 0.01, double offset = 0.0);

}  // namespace semslam
