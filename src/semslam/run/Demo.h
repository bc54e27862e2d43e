#pragma once
// Demo: what `semslam demo` runs. Paper B's max-mixtures with a null hypothesis (mm-nh) over the built-in demo
// log (sim/DemoScenario.h: look-alike landmarks, misclassified labels, clutter, a loop driven twice), and, for
// comparison, the same pipeline given the true associations (known), each through runMethod / writeMethodRun
// (run/RunMethod.h). The folder gets the log (demo_log.jsonl, a valid `semslam run --in` input), mm-nh's run
// folder (metrics.json, trajectory.tum, truth.tum, landmarks, covariances, associations: python/plot_run.py
// draws it) and known's in known/. The folder is built whole or not at all (io/StagedFolder.h).

#include <cstdint>
#include <string>

#include "semslam/models/MeasurementLog.h"
#include "semslam/run/RunMethod.h"

namespace semslam {

struct DemoRun {
  MeasurementLog log;
  std::string logPath;  ///< where the log was written
  MethodRun maxMixture; ///< mm-nh, written into the folder itself
  MethodRun known;      ///< known, written into folder/known
};

/// Simulates the demo log for `seed`, runs mm-nh and known on it and writes everything into `directory`, which
/// must be absent or empty unless `overwrite` (then it is replaced whole). Throws InputError for a `directory`
/// that cannot be written (io/StagedFolder.h).
DemoRun runDemo(const std::string& directory, std::uint64_t seed, bool overwrite = false);

}  // namespace semslam
