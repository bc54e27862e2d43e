#pragma once
// What a method reports at the end of a run, in the types every layer above the estimators shares: the estimators
// (slam/, hybrid/) fill a RunResult, eval/RunEvaluation.h scores it, io/RunFolder.h writes it, run/ drives all
// three. A method leaves a member empty when it does not produce it.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "semslam/geometry/Matrix.h"
#include "semslam/models/HypothesisComponent.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// A landmark as a method estimates it.
struct EstimatedLandmark {
  int id = 0;                          ///< the method's own id (what associations refer to)
  LandmarkState state = Point2(0.0, 0.0);
  Vector classProbabilities;           ///< P(c) for c = 0..M−1; empty when the method estimates no class
};

/// One row of a run folder's associations.csv: what a method decided for one detection.
struct AssociationRecord {
  int step = 0;
  int detection = 0;
  std::optional<int> landmark;   // nullopt: the null hypothesis
  double weight = 1.0;
  std::optional<int> truth;      // a landmark id, kNotALandmark for clutter, kUnknownTruth, nullopt when absent
  /// rᵀ R⁻¹ r of the detection against its landmark at the final estimate (R: the detection's own covariance,
  /// no state uncertainty): the consistency of the decision with the map. nullopt: no landmark, or a method that
  /// does not report it (the hybrid belief).
  std::optional<double> chi2;
};

/// One decision of paper B's front end taken on the true history (SemanticSlamOptions::decideOnTrueHistory): the
/// landmark it decided and the landmark the true history had for the detection's object at that step. nullopt is
/// "unassigned" in `decided` and "clutter, or an object not mapped before the step" in `right`, so a decision is
/// right exactly when the two are equal.
struct HistoryDecision {
  std::optional<int> decided;
  std::optional<int> right;
};

/// What a method reports at the end of a run. Leave a member empty when the method does not produce it.
struct RunResult {
  std::string method;
  std::vector<Pose> poses;                                     ///< final estimate of each step's pose
  std::vector<Matrix> poseCovariances;                         ///< marginal covariance of each pose (tangent)
  std::vector<std::vector<std::optional<int>>> associations;   ///< [step][detection]: landmark id or null hypothesis
  std::vector<std::vector<HistoryDecision>> historyDecisions;  ///< [step][detection]: decisions on the true history
  std::vector<EstimatedLandmark> landmarks;
  std::vector<HypothesisComponent> components;                 ///< hybrid belief at the last step
  std::vector<double> heaviestAssociationWeights;              ///< hybrid: max_β P(β | H_k), one per step
  double timeSeconds = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace semslam
