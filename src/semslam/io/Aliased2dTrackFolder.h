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

/// Creates `directory` and writes tracks 0 .. tracks − 1 of `steps` steps; progress(done, tracks) after each.
/// Throws InputError when `directory` names a file.
void writeAliased2dTrackFolder(const std::string& directory, const Aliased2dScenario& scenario, std::uint64_t seed,
                               int tracks, int steps, const std::function<void(int, int)>& progress = {});

}  // namespace semslam
