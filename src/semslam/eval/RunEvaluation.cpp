#include "semslam/eval/RunEvaluation.h"

#include <set>
#include <string>
#include <variant>

#include "semslam/core/InputError.h"

namespace semslam {
namespace {

long long asCount(std::size_t n) { return static_cast<long long>(n); }

void requireOnePerStep(std::size_t size, std::size_t steps, const std::string& what) {
  if (size != 0 && size != steps) {
    throw InputError("run evaluation: " + std::to_string(size) + " " + what + " for " + std::to_string(steps) +
                     " time steps (give one per step, or none)");
  }
}

/// A per-detection list of step `step` (associations, decisions) holds one entry per detection of the step.
void requireOnePerDetection(std::size_t size, std::size_t detections, std::size_t step, const std::string& what) {
  if (size != detections) {
    throw InputError("run evaluation: step " + std::to_string(step) + " has " + std::to_string(detections) +
                     " detections but " + std::to_string(size) + " " + what);
  }
}

double poseNeesOf(const Pose& estimate, const Pose& truth, const Matrix& covariance) {
  if (const SE2* e = std::get_if<SE2>(&estimate)) {
    const SE2* t = std::get_if<SE2>(&truth);
    if (t == nullptr) throw InputError("run evaluation: a 2D pose estimate for a 3D true pose");
    return poseNees(*e, *t, covariance);
  }
  const SE3* t = std::get_if<SE3>(&truth);
  if (t == nullptr) throw InputError("run evaluation: a 3D pose estimate for a 2D true pose");
  return poseNees(std::get<SE3>(estimate), *t, covariance);
}

}  // namespace

void setTrajectoryMetrics(RunMetrics& metrics, const TrajectoryErrors& errors) {
  metrics.alignment = !errors.aligned ? "none" : (errors.dimension == 2 ? "se2" : "se3");
  metrics.poses = asCount(errors.translation.count);
  metrics.ateRmse = errors.translation.rmse;
  metrics.ateMean = errors.translation.mean;
  metrics.ateMedian = errors.translation.median;
  metrics.ateMax = errors.translation.max;
  metrics.rotRmse = errors.rotation.rmse;
  metrics.rotMean = errors.rotation.mean;
  metrics.rotMedian = errors.rotation.median;
  metrics.rotMax = errors.rotation.max;
}

void setDataAssociationMetrics(RunMetrics& metrics, const DataAssociationAccuracy& accuracy) {
  metrics.daAccuracy = accuracy.accuracy;
  metrics.daCorrect = asCount(accuracy.correct);
  metrics.daTotal = asCount(accuracy.total);
  metrics.daNull = asCount(accuracy.nullChosen);
  metrics.daClutter = asCount(accuracy.clutter);
}

void setAssociationErrorMetrics(RunMetrics& metrics, const AssociationErrors& errors) {
  metrics.daAccuracyReal = errors.accuracyReal;
  metrics.pairwisePrecision = errors.pairwisePrecision;
  metrics.pairwiseRecall = errors.pairwiseRecall;
  metrics.clutterRejected = errors.clutterRejected;
  metrics.clutterRejectedMoving = errors.clutterRejectedMoving;
  metrics.clutterRejectedFalsePositive = errors.clutterRejectedFalsePositive;
  metrics.landmarksMerged = asCount(errors.landmarksMerged);
  metrics.landmarksSplit = asCount(errors.landmarksSplit);
  metrics.realUnassigned = errors.realUnassigned;
  metrics.realOnAnotherLandmark = errors.realOnAnotherLandmark;
  metrics.realOnUnmatchedEstimate = errors.realOnUnmatchedEstimate;
}

void setDecisionMetrics(RunMetrics& metrics, const DecisionAccuracy& decisions) {
  metrics.decisionAccuracyReal = decisions.accuracyReal;
  metrics.decisionClutterRejected = decisions.clutterRejectedFraction;
  metrics.decisionsResightingElsewhere = asCount(decisions.resightingsElsewhere);
  metrics.decisionsResightingUnassigned = asCount(decisions.resightingsUnassigned);
  metrics.decisionsFirstSightingForced = asCount(decisions.firstSightingsForced);
}

void setLandmarkMetrics(RunMetrics& metrics, const LandmarkMetrics& landmarks) {
  metrics.landmarksEstimated = asCount(landmarks.estimated);
  metrics.landmarksTrue = asCount(landmarks.truth);
  metrics.landmarkCountError = landmarks.countError;
  metrics.landmarksMatched = asCount(landmarks.matched);
  metrics.landmarkRmse = landmarks.positionRmse;
  metrics.classAccuracy = landmarks.classAccuracy;
}

void setNeesMetrics(RunMetrics& metrics, const NeesSummary& nees) {
  metrics.neesMean = nees.mean;
  metrics.neesCount = asCount(nees.count);
  metrics.neesDof = nees.dimension;
  metrics.neesLower = nees.lower;
  metrics.neesUpper = nees.upper;
}

void setHypothesisMetrics(RunMetrics& metrics, const HypothesisMetrics& hypotheses) {
  metrics.entropy = hypotheses.entropy;
  metrics.detCov = hypotheses.detCovariance;
  metrics.errWmax = hypotheses.errorHeaviest;
  metrics.errWavg = hypotheses.errorWeightedAverage;
  metrics.ess = hypotheses.ess;
  metrics.assocWeightMax = hypotheses.heaviestAssociationWeight;
  metrics.components = asCount(hypotheses.components);
  metrics.histories = asCount(hypotheses.histories);
}

RunEvaluation evaluateRun(const MeasurementLog& log, const RunResult& result, const RunEvaluationOptions& options) {
  const std::size_t steps = log.steps.size();
  requireOnePerStep(result.poses.size(), steps, "pose estimates");
  requireOnePerStep(result.poseCovariances.size(), steps, "pose covariances");
  requireOnePerStep(result.associations.size(), steps, "association lists");
  requireOnePerStep(result.historyDecisions.size(), steps, "decision lists");
  if (!result.poseCovariances.empty() && result.poses.empty()) {
    throw InputError("run evaluation: pose covariances without pose estimates");
  }

  RunEvaluation evaluation;
  RunMetrics& metrics = evaluation.metrics;
  metrics.method = result.method;
  metrics.dimension = log.header.dimension;
  metrics.timeSeconds = result.timeSeconds;

  // Trajectory and NEES, on the steps with a true pose.
  if (!result.poses.empty()) {
    std::vector<Pose> estimate, truth;
    std::vector<double> nees;
    for (std::size_t i = 0; i < steps; ++i) {
      if (!log.steps[i].truePose) continue;
      estimate.push_back(result.poses[i]);
      truth.push_back(*log.steps[i].truePose);
      if (!result.poseCovariances.empty()) {
        nees.push_back(poseNeesOf(result.poses[i], *log.steps[i].truePose, result.poseCovariances[i]));
      }
    }
    if (!estimate.empty()) {
      const bool align = options.alignTrajectory && estimate.size() >= 2;
      try {
        evaluation.trajectory = evaluateTrajectoryErrors(estimate, truth, align);
      } catch (const InputError&) {
        if (!align) throw;
        evaluation.trajectory = evaluateTrajectoryErrors(estimate, truth, false);  // degenerate alignment
      }
      setTrajectoryMetrics(metrics, *evaluation.trajectory);
    }
    if (!result.poseCovariances.empty() && !nees.empty()) {
      const int d = std::holds_alternative<SE2>(result.poses.front()) ? 3 : 6;
      evaluation.nees = summarizeNees(nees, d, options.neesConfidence);
      setNeesMetrics(metrics, *evaluation.nees);
    }
  }

  // Data association, on the detections with a scored truth id (a landmark or clutter; kUnknownTruth is left out
  // as a detection without truth is: docs/metrics.md).
  bool detectionTruth = false;
  std::set<int> knowable;  // true landmarks the method could know: detected, or given as priors
  for (const TimeStep& step : log.steps) {
    for (const Detection& d : step.detections) {
      const std::optional<int> truth = scoredTruth(d.truthId);
      if (!truth) continue;
      detectionTruth = true;
      if (*truth != kNotALandmark) knowable.insert(*truth);
    }
  }
  if (!result.associations.empty()) {
    std::vector<DetectionAssociation> pairs;
    for (std::size_t i = 0; i < steps; ++i) {
      const std::vector<Detection>& detections = log.steps[i].detections;
      const std::vector<std::optional<int>>& associated = result.associations[i];
      requireOnePerDetection(associated.size(), detections.size(), i, "associations");
      for (std::size_t j = 0; j < detections.size(); ++j) {
        if (const std::optional<int> truth = scoredTruth(detections[j].truthId)) {
          const std::optional<int> source = *truth == kNotALandmark ? detections[j].clutterSource : std::nullopt;
          pairs.push_back({*truth, associated[j], source});
        }
      }
    }
    if (!pairs.empty()) {
      evaluation.dataAssociation = evaluateDataAssociation(pairs);
      setDataAssociationMetrics(metrics, *evaluation.dataAssociation);
      evaluation.associationErrors = evaluateAssociationErrors(pairs, evaluation.dataAssociation->matching);
      setAssociationErrorMetrics(metrics, *evaluation.associationErrors);
    }
  }

  if (!result.historyDecisions.empty()) {
    std::vector<ScoredDecision> scored;
    for (std::size_t i = 0; i < steps; ++i) {
      const std::vector<Detection>& detections = log.steps[i].detections;
      requireOnePerDetection(result.historyDecisions[i].size(), detections.size(), i, "decisions");
      for (std::size_t j = 0; j < detections.size(); ++j) {
        if (const std::optional<int> truth = scoredTruth(detections[j].truthId)) {
          scored.push_back({*truth, result.historyDecisions[i][j]});
        }
      }
    }
    if (!scored.empty()) {
      evaluation.decisions = evaluateDecisions(scored);
      setDecisionMetrics(metrics, *evaluation.decisions);
    }
  }

  // Landmarks.
  std::vector<LandmarkTruth> trueLandmarks;
  std::optional<std::size_t> trueCount;
  if (detectionTruth) {
    for (const LandmarkPrior& prior : log.header.landmarkPriors) knowable.insert(prior.id);
    for (const LandmarkTruth& t : log.header.landmarkTruth) {
      if (knowable.count(t.id) != 0) trueLandmarks.push_back(t);
    }
    trueCount = knowable.size();
  } else if (!log.header.landmarkTruth.empty()) {
    trueLandmarks = log.header.landmarkTruth;
    trueCount = trueLandmarks.size();
  }
  const SimilarityTransform alignment =
      evaluation.trajectory && evaluation.trajectory->aligned ? evaluation.trajectory->alignment : SimilarityTransform{};
  const LandmarkMatching matching = evaluation.dataAssociation ? evaluation.dataAssociation->matching : LandmarkMatching{};
  evaluation.landmarks = evaluateLandmarks(result.landmarks, trueLandmarks, matching, alignment);
  if (trueCount) {
    evaluation.landmarks->truth = *trueCount;
    evaluation.landmarks->countError = asCount(result.landmarks.size()) - asCount(*trueCount);
  }
  setLandmarkMetrics(metrics, *evaluation.landmarks);
  if (!trueCount) {
    metrics.landmarksTrue = std::nullopt;
    metrics.landmarkCountError = std::nullopt;
  }
  if (!evaluation.dataAssociation) metrics.landmarksMatched = std::nullopt;

  // Hybrid belief.
  if (!result.components.empty()) {
    const std::optional<Pose> lastTruth = steps > 0 ? log.steps.back().truePose : std::nullopt;
    evaluation.hypotheses = evaluateHypotheses(result.components, lastTruth, options.disambiguationThreshold);
    setHypothesisMetrics(metrics, *evaluation.hypotheses);
  }
  if (!result.heaviestAssociationWeights.empty()) {
    metrics.disambiguatedFraction =
        disambiguatedFraction(result.heaviestAssociationWeights, options.disambiguationThreshold);
  }
  return evaluation;
}

}  // namespace semslam
