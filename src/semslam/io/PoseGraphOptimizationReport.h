#pragma once
// PoseGraphOptimizationReport: what `semslam optimize` reports about one pose-graph file, a batch solve or an
// incremental replay (run/PoseGraphOptimization.h computes it), and its JSON file (`--report`), whose keys are:
//   both         file, format, solver (gn | lm | incremental), variables, edges, initial_chi2, final_chi2, time_s
//                (chi2 over the file's own edges: the anchoring prior excluded), version (the semslam release,
//                core/Version.h)
//   batch        iterations, converged, stop_reason, initial_gradient_norm, final_gradient_norm
//   incremental  steps, replay_time_s, worst_step_time_s, worst_step, final_convergence,
//                final_convergence_time_s, final_convergence_iterations, relinearize_threshold, relinearize_skip,
//                wildfire_threshold, mean_reeliminated_variables, mean_relinearized_variables, mean_solved_cliques,
//                full_reorderings, cliques, factor_entries
//   --marginals  marginals {id: covariance rows}, joint_marginal {keys, matrix}
// and the step times' CSV (`--step-times`: step,seconds).

#include <optional>
#include <string>
#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"
#include "semslam/solve/IncrementalSmoother.h"
#include "semslam/solve/JointMarginal.h"
#include "semslam/solve/Optimizer.h"

namespace semslam {

/// The incremental replay's own figures (optimize --incremental).
struct PoseGraphReplayStatistics {
  std::size_t steps = 0;
  std::vector<double> stepSeconds;  ///< every step's wall time
  double replaySeconds = 0.0;       ///< the whole replay
  double worstStepSeconds = 0.0;
  std::size_t worstStep = 0;
  double checksum = 0.0;            ///< sum of the newest poses' dimensions (the reads are real)
  bool finalConvergence = true;     ///< whether the whole graph was converged after the replay
  double finalConvergenceSeconds = 0.0;
  IncrementalSmootherParams params;
  double meanReeliminatedVariables = 0.0, meanRelinearizedVariables = 0.0, meanSolvedCliques = 0.0;
  int fullReorderings = 0;
  std::size_t cliques = 0, factorEntries = 0;
};

struct PoseGraphOptimizationReport {
  std::string file;
  std::string format;  ///< g2o | toro | isam
  std::string solver;  ///< gn | lm | incremental
  std::size_t variables = 0, edges = 0;
  double initialChi2 = 0.0, finalChi2 = 0.0;
  double seconds = 0.0;  ///< batch: the solve; incremental: the replay + the final convergence
  /// Batch: the solve. Incremental: the final convergence (iterations 0 when disabled).
  OptimizationResult result;
  Values estimate;                          ///< the final estimate
  FactorGraph graph;                        ///< the file's own edges (for writing the optimised graph)
  std::vector<Key> fixed;                   ///< the file's FIX vertices
  std::optional<JointMarginal> marginals;   ///< of the --marginals keys, in their order
  std::optional<PoseGraphReplayStatistics> replay;  ///< incremental only
};

/// The report as JSON text (2-space indent, keys sorted, a final newline).
std::string poseGraphReportJson(const PoseGraphOptimizationReport& report);

/// Writes poseGraphReportJson atomically.
void writePoseGraphReport(const std::string& path, const PoseGraphOptimizationReport& report);

/// "step,seconds" then one row per step, written atomically.
void writeReplayStepTimes(const std::string& path, const std::vector<double>& stepSeconds);

}  // namespace semslam
