#pragma once
// Scoring one run: a method fills a RunResult (what it estimated), evaluateRun compares it with the ground truth
// of the measurement log it ran on and gives the RunMetrics of metrics.json (RunMetrics.h, docs/metrics.md).
// Methods do not compute metrics themselves; they only report their final estimate.
//
// What is compared, and when each group of fields is filled (otherwise it stays null):
//   trajectory   result.poses (one per log step) against the steps' true poses, on the steps that have one:
//                ATE and rotation errors after SE(2)/SE(3) Umeyama alignment (TrajectoryMetrics.h). With fewer than
//                two true poses, or when the alignment is degenerate (e.g. the robot never moved), the errors are
//                taken without alignment and "alignment" says "none".
//   association  result.associations (per step, per detection: the estimated landmark id the final estimate uses,
//                or std::nullopt for the null hypothesis; a detection that created a landmark names it) against the
//                detections' truth ids, on the detections that have one (DataAssociationAccuracy.h), and the
//                errors by kind through the same matching (AssociationErrors.h).
//   landmarks    landmarks_estimated = result.landmarks.size(). landmarks_true = the true landmarks the method
//                could know: those detected at least once plus those given to it as priors (header
//                landmarkPriors), when the log has detection truth; else the header's landmark truth count.
//                RMSE and class accuracy use the association matching and the trajectory's alignment (identity
//                when the trajectory was not aligned) (LandmarkMetrics.h).
//   NEES         result.poseCovariances (one per step, right perturbation) with result.poses, on the steps with a
//                true pose, unaligned: d = 3 (SE2) or 6 (SE3), band at `neesConfidence` (Nees.h).
//   hybrid       result.components (the final belief) against the last step's true pose (HypothesisMetrics.h);
//                disambiguated_fraction from result.heaviestAssociationWeights (one per step).
//   time_s       result.timeSeconds, as measured by the caller.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "semslam/eval/AssociationErrors.h"
#include "semslam/eval/DataAssociationAccuracy.h"
#include "semslam/eval/DecisionAccuracy.h"
#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/eval/LandmarkMetrics.h"
#include "semslam/eval/Nees.h"
#include "semslam/eval/RunMetrics.h"
#include "semslam/eval/TrajectoryMetrics.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/models/RunResult.h"

namespace semslam {

struct RunEvaluationOptions {
  bool alignTrajectory = true;
  double neesConfidence = 0.95;
  double disambiguationThreshold = 0.9;
};

/// The metrics and the details behind them.
struct RunEvaluation {
  RunMetrics metrics;
  std::optional<TrajectoryErrors> trajectory;
  std::optional<DataAssociationAccuracy> dataAssociation;
  std::optional<AssociationErrors> associationErrors;
  std::optional<DecisionAccuracy> decisions;  ///< runs with decisions on the true history only
  std::optional<LandmarkMetrics> landmarks;
  std::optional<NeesSummary> nees;
  std::optional<HypothesisMetrics> hypotheses;
};

/// Scores `result` against `log`. Throws InputError when the result's sizes do not fit the log (poses,
/// covariances or association lists not one per step, an association list not one per detection).
RunEvaluation evaluateRun(const MeasurementLog& log, const RunResult& result, const RunEvaluationOptions& options = {});

// Copying one group of results into RunMetrics (evaluateRun uses these; so can a caller with its own pipeline).
void setTrajectoryMetrics(RunMetrics& metrics, const TrajectoryErrors& errors);
void setDataAssociationMetrics(RunMetrics& metrics, const DataAssociationAccuracy& accuracy);
void setAssociationErrorMetrics(RunMetrics& metrics, const AssociationErrors& errors);
void setLandmarkMetrics(RunMetrics& metrics, const LandmarkMetrics& landmarks);
void setNeesMetrics(RunMetrics& metrics, const NeesSummary& nees);
void setHypothesisMetrics(RunMetrics& metrics, const HypothesisMetrics& hypotheses);

}  // namespace semslam
