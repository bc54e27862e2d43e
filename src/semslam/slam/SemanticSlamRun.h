#pragma once
// Running paper B's pipeline (SemanticSlam.h) over a whole measurement log: the run behind `semslam run
// --method known|ml|gpda|mm|mm-nh` and each cell of `semslam study robustness`.

#include "semslam/eval/RunEvaluation.h"
#include "semslam/io/RunFolder.h"
#include "semslam/slam/SemanticSlam.h"

namespace semslam {

struct SemanticSlamRun {
  RunResult result;          ///< the final estimate, timeSeconds = the pipeline's wall time (evaluation excluded)
  RunEvaluation evaluation;  ///< scored against the log's truth
  RunOutput output;          ///< the run folder's contents
  std::size_t factors = 0;   ///< factors in the final graph
};

struct SemanticSlamRunOptions {
  SemanticSlamOptions slam;
  bool poseCovariances = true;  ///< marginal covariance of every pose in the result (NEES, covariance ellipses)
  bool runFolder = true;        ///< fill `output`
};

SemanticSlamRun runSemanticSlam(const MeasurementLog& log, const SemanticSlamRunOptions& options);

}  // namespace semslam
