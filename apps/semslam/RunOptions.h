#pragma once
// The options of one method run, as `semslam run` takes them, written once for every caller that runs a method
// from flags: the `run` command (RunCommand.cpp) and the Python module's `semslam.run(method, log, **options)`
// (bindings/python/RunBindings.cpp), whose keyword arguments are these flags with `_` for `-`. A flag therefore
// means the same thing, with the same checks and defaults, in the shell and in Python.
//
//   --method, --smoother, paper B's options (MethodOptions.h: addSemanticSlamOptions), --no-covariances,
//   --on-known-trajectory, --pose-error-scale, --on-true-history, --seed, paper A's options (addHybridOptions)
//
// The input and output (--in, --out, --overwrite) and the progress line (--quiet) stay the run command's own.

#include <CLI/CLI.hpp>
#include <string>

#include "semslam/run/RunMethod.h"

namespace semslam::cli {

struct RunMethodArguments {
  std::string method = "mm-nh";
  std::string smoother;  // empty: the method's default (incremental for paper B, batch LM for the hybrid belief)
  bool noCovariances = false;
  bool onKnownTrajectory = false;
  bool onTrueHistory = false;
  double poseErrorScale = 0.0;
  std::string poseErrorDraw = "joint";
  MethodOptions options;
};

/// Binds the flags above to `arguments`.
void addRunMethodOptions(CLI::App* command, RunMethodArguments& arguments);

/// Runs the method the arguments name over `log` (run/RunMethod.h: runMethod, or run/KnownTrajectoryCeiling.h with
/// --on-known-trajectory). A log the method cannot take throws InputError(source, 0, reason): `source` names the
/// log (its file, or a description of a log held in memory).
MethodRun runFromArguments(const MeasurementLog& log, RunMethodArguments arguments, const std::string& source,
                           const RunProgress& progress = {});

}  // namespace semslam::cli
