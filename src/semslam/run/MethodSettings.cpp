#include "semslam/run/MethodSettings.h"

#include "semslam/slam/LoopClosureBranches.h"
#include "semslam/slam/SemanticSlamSmoother.h"

namespace semslam {
namespace {

/// The value, or null where it is unset.
nlohmann::json optionalJson(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

/// Paper B's front end, each default resolved for the strategy of `options` (set by the caller from the method).
nlohmann::json associationSettings(const SemanticSlamOptions& options) {
  return {
      {"birth", birthRuleName(options.birth)},
      {"gate", options.gateConfidence},
      {"unassigned_rate", options.unassignedRate},
      {"unassigned_rate_weight", optionalJson(options.unassignedRateWeight)},
      {"unassigned_rate_memory", optionalJson(options.unassignedRateMemory)},
      {"confirmations", options.provisional.confirmations},
      {"confirmation_spacing", options.provisional.spacingSeconds},
      {"confirmation_viewpoint", options.provisional.viewpointDistance},
      {"confirmation_viewpoint_sigmas", options.provisional.viewpointSigmas},
      {"patience", options.provisional.patience},
      {"assignment_score", assignmentScoreName(resolvedAssignmentScore(options))},
      {"null_weight", options.nullWeight},
      {"null_sigma_scale", options.nullSigmaScale},
      {"null_escape", options.nullEscape},
      {"null_escape_window", options.nullEscapeWindow},
      {"warm_start", options.warmStart},
      {"warm_start_posterior", options.warmStartMinimumPosterior},
      {"em_window", options.emWindow},
      {"em_iterations", options.emIterations},
      {"minimum_gpda_weight", options.minimumGpdaWeight},
      {"label_split", options.labelSplit},
      {"anchoring_information", options.anchoringInformation},
      {"loop_closure_branches", LoopClosureBranches::window(options)},
      {"loop_closure_next_best", LoopClosureBranches::nextBest(options)},
      {"loop_closure_apart_keeps_merges", options.loopClosureApartKeepsMerges},
      {"loop_closure_open_splits", LoopClosureBranches::maximumOpenSplits(options)},
      {"candidate_preselection", options.candidatePreselection},
      {"on_true_history", options.decideOnTrueHistory},
  };
}

nlohmann::json hybridSettings(const HybridOptions& options) {
  return {
      {"semantics", options.useSemantics},
      {"weights", weightMethodName(options.weights)},
      {"samples", options.samples},
      {"importance_iterations", options.importanceIterations},
      {"prune_ratio", options.pruneRatio},
      {"gate_ratio", options.gateRatio},
      {"branching", options.branching == Branching::WholeAssociation ? "whole" : "one-at-a-time"},
      {"joint_compatibility", options.jointCompatibility},
      {"max_components", options.maxComponents},
      {"max_candidates", options.maxCandidates},
      {"max_memory", options.maxMemoryMiB},
      {"enumerate_all_classes", options.enumerateAllClasses},
      {"visibility", options.visibility},
      {"seed", options.seed},
  };
}

}  // namespace

nlohmann::json methodSettings(const MethodOptions& options) {
  nlohmann::json settings = {{"method", methodName(options.method)}, {"pose_covariances", options.poseCovariances}};
  if (isHybrid(options.method)) {
    settings["back_end"] = {{"smoother", smootherKindName(options.smoother.value_or(SmootherKind::Batch))}};
    HybridOptions hybrid = options.hybrid;
    hybrid.useSemantics = options.method == Method::Hybrid;
    settings["hybrid"] = hybridSettings(hybrid);
    return settings;
  }
  // The back end: incremental unless chosen, or a factory given in code (the studies' --smoother); the
  // relinearization settings are the incremental back end's only.
  const bool callers = !options.smoother && options.slam.smoother;
  const SmootherKind kind = options.smoother.value_or(SmootherKind::Incremental);
  const bool incremental = !callers && kind == SmootherKind::Incremental;
  const IncrementalSmootherParams defaults = semanticSlamSmootherParams();
  const nlohmann::json null(nullptr);
  settings["back_end"] = {
      {"smoother", callers ? std::string("caller's") : smootherKindName(kind)},
      {"relinearize_threshold",
       incremental ? nlohmann::json(options.relinearizeThreshold.value_or(defaults.relinearizeThreshold)) : null},
      {"relinearize_skip",
       incremental ? nlohmann::json(options.relinearizeSkip.value_or(defaults.relinearizeSkip)) : null},
      {"switch_rounds", options.switchRounds},
  };
  SemanticSlamOptions slam = options.slam;
  slam.strategy = associationStrategy(options.method);
  settings["association"] = associationSettings(slam);
  return settings;
}

}  // namespace semslam
