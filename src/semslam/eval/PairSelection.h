#pragma once
// Which pose pairs (i, j) the relative pose error compares: evo's metrics.id_pairs_from_delta with
// filters.filter_pairs_by_index / filter_pairs_by_path (evo/core/filters.py), on one trajectory's positions.
//
// frames, consecutive (default):  ids = 0, Δ, 2Δ, ... < n;  pairs (ids[k], ids[k+1]).
// frames, all pairs:              (i, i + Δ) for every i with i + Δ < n.
// metres, consecutive (default):  walk the trajectory accumulating the distance between consecutive positions
//                                 (starting at pose 0 with 0); each time it reaches >= Δ, record the pose index and
//                                 restart from 0; pairs are consecutive recorded indices. NOTE: the first recorded
//                                 index is the first pose Δ metres along the path, not pose 0 (evo's behaviour).
// metres, all pairs:              with d_k the accumulated path length at pose k, for each i < n−1 the j > i with
//                                 |d_j − d_i − Δ| smallest (first on ties), kept when within tol = Δ · rel_tol.
//
// evo takes the pairs from the ESTIMATED trajectory by default (metrics.RPE, pairs_from_reference = False); the
// caller chooses which trajectory to pass. No pair at all throws InputError, as evo raises there.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "semslam/models/Trajectory.h"

namespace semslam {

enum class DeltaUnit { Frames, Meters };

/// "frames" (or "f") | "m" (or "meters"); anything else throws InputError.
DeltaUnit parseDeltaUnit(const std::string& name);
std::string toString(DeltaUnit unit);

using PosePair = std::pair<std::size_t, std::size_t>;

/// The pairs of `trajectory` for `delta` in `unit` (see above). delta must be > 0, and a whole number for frames;
/// relativeTolerance (only for metres with allPairs) must be >= 0. Throws InputError otherwise or when no pair.
std::vector<PosePair> selectPosePairs(const Trajectory& trajectory, double delta, DeltaUnit unit,
                                      bool allPairs = false, double relativeTolerance = 0.1);

}  // namespace semslam
