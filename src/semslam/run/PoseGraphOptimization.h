#pragma once
// PoseGraphOptimization: `semslam optimize` as one library call. Reads a pose-graph file (g2o, TORO or iSAM) and
//   batch        optimises the file's edges plus the first-pose anchor (io/PoseGraphAnchor.h) by Gauss-Newton or
//                Levenberg-Marquardt from the file's initial values (solve/Optimizer.h);
//   incremental  replays it pose by pose through the incremental smoother (run/PoseGraphReplayLoop.h: one update
//                per pose, the newest pose read after every update), then, unless disabled, converges the whole
//                graph once by Gauss-Newton (IncrementalSmoother::convergeAll) so that final_chi2 is the optimum;
// and, for the --marginals ids, their marginal and joint covariance at the final estimate. The report and its JSON
// are io/PoseGraphOptimizationReport.h.

#include <functional>
#include <string>

#include "semslam/io/PoseGraphOptimizationReport.h"
#include "semslam/solve/IncrementalSmoother.h"
#include "semslam/solve/Optimizer.h"

namespace semslam {

struct PoseGraphOptimizationOptions {
  std::string file;
  std::string format = "g2o";  ///< g2o | toro | isam
  SolverType solver = SolverType::GaussNewton;  ///< batch
  int maxIterations = 100;     ///< batch, and the incremental replay's final convergence
  bool verbose = false;        ///< batch: one line per iteration on stderr
  std::string marginals;       ///< comma-separated ids (x12,l3 for iSAM); empty: none
  bool incremental = false;
  bool finalConvergence = true;               ///< incremental
  IncrementalSmootherParams incrementalParams;  ///< incremental
  /// incremental: called after each replayed step with (steps done, steps in all); the CLI draws core/ProgressBar.
  std::function<void(int done, int total)> progress;
};

/// Throws InputError for an unreadable file, a bad --marginals id list, and a result with a non-finite chi2,
/// gradient or estimate (never reported as a success: the file's numbers are too large).
PoseGraphOptimizationReport optimizePoseGraphFile(const PoseGraphOptimizationOptions& options);

}  // namespace semslam
