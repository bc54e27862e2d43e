#pragma once
// MethodSettings: what a method run was made with, as JSON, so that a run folder says how to make it again and two
// folders can be compared option by option. Every option of the run's estimator is written with the value the run
// used: an option left to its default is written as the default the method resolved it to (the loop-closure
// window of mm-nh, 16; of gpda, 0), never as "unset". Written by writeMethodRun as the run folder's settings.json
// (schema "semslam.settings/1", with the semslam release) and by the robustness study as study.json's
// `method_settings`, one entry per method (docs/file-formats.md, "settings.json").
//
//   method             the method's name (run/Method.h)
//   pose_covariances   whether each pose's marginal covariance was computed
//   back_end           paper B: smoother ("incremental", "batch", or "caller's" for a factory given in code),
//                      relinearize_threshold and relinearize_skip (the incremental back end's), switch_rounds;
//                      paper A: smoother ("batch": Levenberg-Marquardt per component, or the one chosen)
//   association        paper B's methods: every SemanticSlamOptions field (slam/SemanticSlam.h), by its CLI name
//                      with `_` for `-`; unassigned_rate_weight null where μ is a constant
//   hybrid             paper A's methods: every HybridOptions field (hybrid/HybridOptions.h), the same way
//
// A run on a known trajectory (run/KnownTrajectoryCeiling.h) adds `on_known_trajectory` (pose_error_scale,
// pose_error_draw, seed) where it is made.

#include <nlohmann/json.hpp>

#include "semslam/run/RunMethod.h"

namespace semslam {

/// The settings of a run of `options.method` with `options` (as above). Throws std::invalid_argument for options
/// the method refuses, as runMethod does.
nlohmann::json methodSettings(const MethodOptions& options);

}  // namespace semslam
