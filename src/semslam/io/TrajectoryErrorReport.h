#pragma once
// TrajectoryErrorReport: `semslam eval ate|rpe` as library calls. evaluateTrajectoryFiles reads a reference and an
// estimated trajectory file (TUM, KITTI or EuRoC) and computes the absolute or relative pose error exactly as evo
// does (eval/TrajectoryEvaluation.h); the result is then printed either as evo's Result.pretty_str (the title, a
// blank line, the statistics sorted by name as "%10s\t%.6f", then a line of counts) or as a JSON object (metric,
// relation, unit, align, reference, estimate, rmse, mean, median, max, min, sse, std, pairs, associated_poses,
// version (the semslam release, core/Version.h); scale when aligned with scale; delta, delta_unit, all_pairs for
// rpe). docs/evaluation.md.

#include <string>

#include "semslam/eval/TrajectoryEvaluation.h"
#include "semslam/io/TrajectoryFormat.h"

namespace semslam {

struct TrajectoryErrorRequest {
  bool relative = false;  ///< rpe instead of ate
  std::string reference, estimate;  ///< file paths
  TrajectoryFormat referenceFormat = TrajectoryFormat::Tum, estimateFormat = TrajectoryFormat::Tum;
  EvaluationOptions options;
};

/// Reads both files and evaluates; throws InputError for a bad file, and for statistics that overflow (finite but
/// huge coordinates: the file with the largest one is named, with the pose).
EvaluationResult evaluateTrajectoryFiles(const TrajectoryErrorRequest& request);

/// evo's text (pretty_str) and the counts line, newline-terminated.
std::string trajectoryErrorText(const TrajectoryErrorRequest& request, const EvaluationResult& result);

/// The JSON object, 2-space indent, newline-terminated.
std::string trajectoryErrorJson(const TrajectoryErrorRequest& request, const EvaluationResult& result);

}  // namespace semslam
