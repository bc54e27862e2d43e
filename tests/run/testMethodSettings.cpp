// run/MethodSettings.h: a run folder's settings.json records every option the run was made with, each default
// resolved as the method resolves it, so that a folder says how to make it again.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "semslam/core/Version.h"
#include "semslam/run/KnownTrajectoryCeiling.h"
#include "semslam/run/MethodSettings.h"
#include "semslam/slam/LoopClosureBranches.h"
#include "support/SmallSemanticRun.h"
#include "io/IoTesting.h"

namespace semslam {
namespace {

MethodOptions optionsFor(Method method) {
  MethodOptions options;
  options.method = method;
  return options;
}

TEST(MethodSettings, PaperBsDefaultsAreWrittenAsEachMethodResolvesThem) {
  const nlohmann::json mmnh = methodSettings(optionsFor(Method::MaxMixtureNullHypothesis));
  EXPECT_EQ(mmnh["method"], "mm-nh");
  EXPECT_FALSE(mmnh.contains("hybrid"));
  const nlohmann::json& association = mmnh["association"];
  EXPECT_EQ(association["loop_closure_branches"], LoopClosureBranches::kDefaultWindow);
  EXPECT_EQ(association["loop_closure_next_best"], true);
  EXPECT_EQ(association["loop_closure_open_splits"], LoopClosureBranches::kDefaultOpenSplits);
  EXPECT_EQ(association["assignment_score"], "joint");
  EXPECT_EQ(association["birth"], "unassigned");
  EXPECT_TRUE(association["unassigned_rate_weight"].is_null());  // μ constant
  EXPECT_EQ(mmnh["back_end"]["smoother"], "incremental");
  // Paper B's relinearization (slam/SemanticSlamSmoother.h).
  EXPECT_DOUBLE_EQ(mmnh["back_end"]["relinearize_threshold"].get<double>(), 0.05);
  EXPECT_EQ(mmnh["back_end"]["relinearize_skip"], 1);
  // The same option unset resolves per method: gpda has no branches, ml no third branch.
  const nlohmann::json gpda = methodSettings(optionsFor(Method::Gpda));
  EXPECT_EQ(gpda["association"]["loop_closure_branches"], 0);
  EXPECT_EQ(gpda["association"]["loop_closure_next_best"], false);
  EXPECT_EQ(methodSettings(optionsFor(Method::MaximumLikelihood))["association"]["loop_closure_next_best"], false);
  EXPECT_EQ(methodSettings(optionsFor(Method::Known))["association"]["loop_closure_branches"], 0);
  // The batch back end has no relinearization to record.
  MethodOptions batch = optionsFor(Method::MaxMixtureNullHypothesis);
  batch.smoother = SmootherKind::Batch;
  EXPECT_EQ(methodSettings(batch)["back_end"]["smoother"], "batch");
  EXPECT_TRUE(methodSettings(batch)["back_end"]["relinearize_threshold"].is_null());
}

TEST(MethodSettings, EveryOptionOfPaperBsFrontEndIsRecorded) {
  // Each option moved off its default changes its own entry and no other: an option missing from the record, or
  // recorded under another's key, fails here.
  const std::vector<std::pair<std::string, std::function<void(SemanticSlamOptions&)>>> changes = {
      {"birth", [](SemanticSlamOptions& o) { o.birth = BirthRule::Threshold; }},
      {"gate", [](SemanticSlamOptions& o) { o.gateConfidence = 0.99; }},
      {"unassigned_rate", [](SemanticSlamOptions& o) { o.unassignedRate = 0.3; }},
      {"unassigned_rate_weight", [](SemanticSlamOptions& o) { o.unassignedRateWeight = 100.0; }},
      {"unassigned_rate_memory", [](SemanticSlamOptions& o) { o.unassignedRateMemory = 50.0; }},
      {"confirmations", [](SemanticSlamOptions& o) { o.provisional.confirmations = 3; }},
      {"confirmation_spacing", [](SemanticSlamOptions& o) { o.provisional.spacingSeconds = 2.0; }},
      {"confirmation_viewpoint", [](SemanticSlamOptions& o) { o.provisional.viewpointDistance = 1.5; }},
      {"confirmation_viewpoint_sigmas", [](SemanticSlamOptions& o) { o.provisional.viewpointSigmas = 1.0; }},
      {"patience", [](SemanticSlamOptions& o) { o.provisional.patience = 20; }},
      {"assignment_score", [](SemanticSlamOptions& o) { o.assignmentScore = AssignmentScore::Independent; }},
      {"null_weight", [](SemanticSlamOptions& o) { o.nullWeight = 0.3; }},
      {"null_sigma_scale", [](SemanticSlamOptions& o) { o.nullSigmaScale = 20.0; }},
      {"null_escape", [](SemanticSlamOptions& o) { o.nullEscape = false; }},
      {"null_escape_window", [](SemanticSlamOptions& o) { o.nullEscapeWindow = 3.0; }},
      {"warm_start", [](SemanticSlamOptions& o) { o.warmStart = false; }},
      {"warm_start_posterior", [](SemanticSlamOptions& o) { o.warmStartMinimumPosterior = 0.5; }},
      {"em_window", [](SemanticSlamOptions& o) { o.emWindow = 4; }},
      {"em_iterations", [](SemanticSlamOptions& o) { o.emIterations = 5; }},
      {"minimum_gpda_weight", [](SemanticSlamOptions& o) { o.minimumGpdaWeight = 1e-3; }},
      {"label_split", [](SemanticSlamOptions& o) { o.labelSplit = true; }},
      {"anchoring_information", [](SemanticSlamOptions& o) { o.anchoringInformation = 3.0; }},
      {"loop_closure_branches", [](SemanticSlamOptions& o) { o.loopClosureBranchWindow = 8; }},
      {"loop_closure_next_best", [](SemanticSlamOptions& o) { o.loopClosureNextBest = false; }},
      {"loop_closure_apart_keeps_merges", [](SemanticSlamOptions& o) { o.loopClosureApartKeepsMerges = false; }},
      {"loop_closure_open_splits", [](SemanticSlamOptions& o) { o.loopClosureOpenSplits = 1; }},
      {"candidate_preselection", [](SemanticSlamOptions& o) { o.candidatePreselection = false; }},
      {"on_true_history", [](SemanticSlamOptions& o) { o.decideOnTrueHistory = true; }},
  };
  // The entries resolved from others may move with them: the threshold birth rule and decisions on the true history
  // have no loop-closure branches (and the threshold rule no step assignment to score).
  const std::set<std::string> branches = {"loop_closure_branches", "loop_closure_next_best",
                                          "loop_closure_open_splits"};
  std::map<std::string, std::set<std::string>> resolvedWith = {{"birth", branches}, {"on_true_history", branches}};
  resolvedWith["birth"].insert("assignment_score");
  const nlohmann::json defaults = methodSettings(optionsFor(Method::MaxMixtureNullHypothesis))["association"];
  EXPECT_EQ(defaults.size(), changes.size());  // a recorded entry no change above moves would be untested
  for (const auto& [key, change] : changes) {
    MethodOptions options = optionsFor(Method::MaxMixtureNullHypothesis);
    change(options.slam);
    const nlohmann::json changed = methodSettings(options)["association"];
    for (const auto& [entry, value] : defaults.items()) {
      if (entry == key) {
        EXPECT_NE(changed[entry], value) << key;
      } else if (!resolvedWith[key].count(entry)) {
        EXPECT_EQ(changed[entry], value) << key << " moved " << entry;
      }
    }
  }
  EXPECT_EQ(methodSettings([] {
              MethodOptions options = optionsFor(Method::MaxMixtureNullHypothesis);
              options.slam.birth = BirthRule::Threshold;
              return options;
            }())["association"]["loop_closure_branches"],
            0);
}

TEST(MethodSettings, PaperAsOptionsAreRecordedForTheHybridMethods) {
  MethodOptions options = optionsFor(Method::HybridGeometric);
  options.hybrid.samples = 77;
  options.hybrid.seed = 9;
  const nlohmann::json settings = methodSettings(options);
  EXPECT_FALSE(settings.contains("association"));
  EXPECT_EQ(settings["hybrid"]["semantics"], false);  // the method's, whatever the options say
  EXPECT_EQ(settings["hybrid"]["samples"], 77);
  EXPECT_EQ(settings["hybrid"]["seed"], 9);
  EXPECT_EQ(settings["hybrid"]["weights"], "sampled");
  EXPECT_EQ(settings["back_end"]["smoother"], "batch");
  EXPECT_EQ(methodSettings(optionsFor(Method::Hybrid))["hybrid"]["semantics"], true);
}

TEST(MethodSettings, ARunFolderHoldsTheSettingsItWasMadeWith) {
  const MeasurementLog log = test::smallSemanticLog();
  MethodOptions options = optionsFor(Method::MaximumLikelihood);
  options.poseCovariances = false;
  options.slam.unassignedRateWeight = 50.0;
  const MethodRun run = runMethod(log, options);
  const test::TempDir folder;
  writeMethodRun(folder.path("run"), run);
  std::ifstream in(folder.path("run") + "/settings.json");
  const nlohmann::json written = nlohmann::json::parse(in);
  EXPECT_EQ(written["schema"], "semslam.settings/1");
  EXPECT_EQ(written["version"], std::string(version()));
  nlohmann::json expected = methodSettings(options);
  for (const auto& [key, value] : expected.items()) EXPECT_EQ(written[key], value) << key;
  EXPECT_EQ(written["association"]["unassigned_rate_weight"], 50.0);
  EXPECT_EQ(written["pose_covariances"], false);
  // A run on the known trajectory says so, with what moved it.
  const MethodRun ceiling = runOnKnownTrajectory(log, options, 0.5, 3, PoseErrorDraw::Independent);
  EXPECT_EQ(ceiling.settings["on_known_trajectory"]["pose_error_scale"], 0.5);
  EXPECT_EQ(ceiling.settings["on_known_trajectory"]["pose_error_draw"], "independent");
  EXPECT_EQ(ceiling.settings["on_known_trajectory"]["seed"], 3);
}

}  // namespace
}  // namespace semslam
