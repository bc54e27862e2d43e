#pragma once
// Aliased2dTrackFolder: `semslam simulate aliased2d --tracks N --out DIR` (N > 1): every track of paper A's
// aliased scenario (sim/Aliased2dSimulator.h) written as its own measurement log, DIR/track_NNN.jsonl (at least
// three digits, more when N > 1000), so that track i is the same log however many tracks are asked for.

#include <cstdint>
#include <functional>
#include <string>

#include "semslam/sim/Aliased2dScenario.h"

namespace semslam {

/// "track_007.jsonl" for track 7 of up to 1000 tracks; wider for more.
std::string aliased2dTrackFileName(int track, int tracks);

/// Writes tracks 0 .. tracks − 1 of `steps` steps into `directory`, built whole or not at all (io/StagedFolder.h:
/// an interrupted run leaves no folder that looks finished); progress(done, tracks) after each. `directory` must
/// be absent or empty unless `overwrite` (then it is replaced whole: no stale track of an earlier run stays).
/// Throws InputError when `directory` names a file, a link or a non-empty folder without `overwrite`.
void writeAliased2dTrackFolder(const std::string& directory, const Aliased2dScenario& scenario, std::uint64_t seed,
                               int tracks, int steps, bool overwrite,
                               const std::function<void(int, int)>& progress = {});

}  // namespace semslam
