#pragma once
// The command-line options of the estimation methods, written once and shared by every command that runs a method
// (`semslam run`, `semslam study hybrid`, `semslam study robustness`): each block binds its flags straight into the
// library's option structs (run/RunMethod.h), so a flag means the same thing on every command.

#include <CLI/CLI.hpp>
#include <string>

#include "semslam/hybrid/HybridOptions.h"
#include "semslam/slam/SemanticSlam.h"

namespace semslam::cli {

/// Paper B's pipeline: --gate, --null-weight, --null-sigma-scale, --em-window, --em-iterations, --birth,
/// --confirmations, --confirmation-spacing, --confirmation-viewpoint, --confirmation-viewpoint-sigmas, --patience,
/// --unassigned-rate, --unassigned-rate-weight, --unassigned-rate-memory, --no-warm-start, --no-null-escape,
/// --null-escape-window, --label-split, --loop-closure-branches, --anchoring-information, --warm-start-posterior.
void addSemanticSlamOptions(CLI::App* command, SemanticSlamOptions& options);

/// Paper A's hybrid belief: --samples, --weights, --importance-iterations, --prune-ratio, --gate-ratio, --branching,
/// --joint-compatibility, --max-components, --max-candidates, --max-memory, --no-visibility. The seed is each
/// command's own (a run's draws, or a study's tracks and draws).
void addHybridOptions(CLI::App* command, HybridOptions& options);

}  // namespace semslam::cli
