#include "MethodOptions.h"

#include <cstdint>
#include <map>
#include <string>

#include "semslam/slam/LoopClosureBranches.h"

namespace semslam::cli {

void addSemanticSlamOptions(CLI::App* command, SemanticSlamOptions& options) {
  command->add_option("--gate", options.gateConfidence, "chi-square gate confidence (paper B: 0.9)")
      ->check(CLI::Range(1e-9, 1.0 - 1e-12))
      ->capture_default_str();
  command->add_option("--null-weight", options.nullWeight, "mm-nh: null-hypothesis weight")
      ->check(CLI::Range(1e-9, 1.0 - 1e-9))
      ->capture_default_str();
  command->add_option("--null-sigma-scale", options.nullSigmaScale,
                      "mm-nh: null hypothesis's standard deviations over the detection's")
      ->check(CLI::Range(1.0, 1e9))
      ->capture_default_str();
  command->add_option("--em-window", options.emWindow, "gpda: steps each E-step re-weights")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--em-iterations", options.emIterations, "gpda: E/M rounds per step")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command->add_option("--birth", options.birth,
                      "how unmatched detections start landmarks: threshold (paper B: no landmark passes the gate) or "
                      "unassigned (an unassigned hypothesis, joint assignment; docs/association-front-end.md)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, BirthRule>{{"threshold", BirthRule::Threshold},
                                                                           {"unassigned", BirthRule::Unassigned}}))
      ->default_str("unassigned");
  command->add_option("--confirmations", options.provisional.confirmations,
                      "birth unassigned: detections, each --confirmation-spacing after the last, that confirm a "
                      "provisional landmark (M)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--confirmation-spacing", options.provisional.spacingSeconds,
                      "birth unassigned: the least time between two detections that count towards M, in seconds (the "
                      "log's time unit; docs/association-front-end.md §5)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command->add_option("--confirmation-viewpoint", options.provisional.viewpointDistance,
                      "metres the robot must have moved between two sightings that count towards confirming a "
                      "landmark (0: any)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command->add_option("--confirmation-viewpoint-sigmas", options.provisional.viewpointSigmas,
                      "the same in units of the sighting's position error (its error ellipse's largest sigma; 0: any; "
                      "the larger of the two applies)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command->add_option("--patience", options.provisional.patience,
                      "birth unassigned: steps in the sensor's field after which an unconfirmed landmark is dropped (N)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--unassigned-rate", options.unassignedRate,
                      "birth unassigned: expected unassigned detections (births + clutter) per step")
      ->check(CLI::Range(1e-9, 1e9))
      ->capture_default_str();
  command
      ->add_option_function<double>(
          "--unassigned-rate-weight", [&options](double weight) { options.unassignedRateWeight = weight; },
          "birth unassigned: estimate the rate from the run (detections decided unassigned per step), "
          "--unassigned-rate counting as this many steps of prior data (docs/association-front-end.md §10, \"mu "
          "from the run\"; default: the rate is constant)")
      ->check(CLI::Range(1e-9, 1e9));
  command
      ->add_option_function<double>(
          "--unassigned-rate-memory", [&options](double steps) { options.unassignedRateMemory = steps; },
          "with --unassigned-rate-weight: estimate the rate over about this many recent steps, each step's count "
          "discounted by 1 - 1/M (docs/association-front-end.md §10; default: every step alike)")
      ->check(CLI::Range(1.0, 1e9));
  command->add_flag("--no-warm-start{false}", options.warmStart,
                    "mm, mm-nh: choose mixture components at the odometry prediction (docs/max-mixtures.md)");
  command->add_flag("--no-null-escape{false}", options.nullEscape,
                    "mm-nh: keep a landmark's detections on the null hypothesis even where trying them on it "
                    "together lowers the objective (docs/association-front-end.md §6b)");
  command->add_option("--null-escape-window", options.nullEscapeWindow,
                      "mm-nh: also try a landmark's single detection on the null hypothesis when the landmark was "
                      "seen off null at most this many seconds before it (0: off; docs/association-front-end.md §6c)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command->add_flag("--label-split", options.labelSplit,
                    "birth unassigned: split a landmark whose labels say it holds two objects "
                    "(docs/association-front-end.md §5d)");
  command
      ->add_option_function<int>(
          "--loop-closure-branches", [&options](int window) { options.loopClosureBranchWindow = window; },
          "birth unassigned, ml / mm / mm-nh: where a step closes a loop on an uncertain estimate, keep a second "
          "branch without that closure for this many steps and keep the one the data favour "
          "(docs/association-front-end.md §10; 0: off)")
      ->check(CLI::Range(0, 1000000))
      ->default_str(std::to_string(LoopClosureBranches::kDefaultWindow));
  command->add_flag_function(
      "--loop-closure-next-best,!--no-loop-closure-next-best",
      [&options](std::int64_t count) { options.loopClosureNextBest = count > 0; },
      "with --loop-closure-branches: a third branch in which the closing detections take their next-best landmarks "
      "(docs/association-front-end.md §10; default: on for mm-nh, off for ml and mm)");
  command->add_flag(
      "--loop-closure-apart-keeps-merges,!--no-loop-closure-apart-keeps-merges", options.loopClosureApartKeepsMerges,
      "with --loop-closure-branches: the branch without the closure refuses the step's loop-closing merges of "
      "provisional landmarks too (docs/association-front-end.md §10; default: on)");
  command
      ->add_option_function<int>(
          "--loop-closure-open-splits", [&options](int splits) { options.loopClosureOpenSplits = splits; },
          "with --loop-closure-branches: how many splits may be open at a time, a branch of an open split "
          "splitting again where its step closes a loop (1: one split at a time; docs/association-front-end.md §10; "
          "default: " + std::to_string(LoopClosureBranches::kDefaultOpenSplits) + " where branches apply, 1 elsewhere)")
      ->check(CLI::Range(1, 8));
  command->add_option("--anchoring-information", options.anchoringInformation,
                      "birth unassigned, with --loop-closure-branches: the information, ½ ln det(S R⁻¹) in nats, "
                      "above which a pairing closes a loop")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command
      ->add_option_function<std::string>(
          "--assignment-score",
          [&options](const std::string& name) { options.assignmentScore = parseAssignmentScore(name); },
          "birth unassigned: how a step's joint assignment scores its detections' pairings: independent (each by "
          "its own likelihood, Hungarian) or joint (by the joint density of their innovations, which share the "
          "pose's error: joint compatibility branch and bound; docs/association-front-end.md §4; the default "
          "wherever a method decides)")
      ->check(CLI::IsMember({"independent", "joint"}))
      ->default_str("joint");
  command->add_option("--warm-start-posterior", options.warmStartMinimumPosterior,
                      "mm, mm-nh: warm-start a detection only on a candidate of at least this posterior "
                      "(0: every detection; docs/association-front-end.md)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
}

void addHybridOptions(CLI::App* command, HybridOptions& options) {
  const std::map<std::string, WeightMethod> weights{
      {"sampled", WeightMethod::Sampled}, {"importance", WeightMethod::Importance}, {"analytic", WeightMethod::Analytic}};
  const std::map<std::string, Branching> branching{{"whole", Branching::WholeAssociation},
                                                   {"one-at-a-time", Branching::OneDetectionAtATime}};
  command->add_option("--samples", options.samples, "hybrid: samples per weight (A, eq. 16)")
      ->check(CLI::Range(2, 1000000))
      ->capture_default_str();
  command
      ->add_option("--weights", options.weights,
                   "hybrid: sampled (A, eq. 16-17, plain Monte Carlo), importance (linearised-posterior proposal) or "
                   "analytic (linearised)")
      ->transform(CLI::CheckedTransformer(weights))
      ->default_str("sampled");
  command->add_option("--importance-iterations", options.importanceIterations,
                      "hybrid: importance weights' proposal linearisations (1: at the mean; > 1: iterated)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  command->add_option("--prune-ratio", options.pruneRatio, "hybrid: prune w < w_max / ratio (<= 1: no pruning)")
      ->capture_default_str();
  command->add_option("--gate-ratio", options.gateRatio,
                      "hybrid: skip sampling when the linearised weight < w_max / ratio (<= 1: no gate)")
      ->capture_default_str();
  command->add_option("--branching", options.branching, "hybrid: whole (every association of a step) or one-at-a-time")
      ->transform(CLI::CheckedTransformer(branching))
      ->default_str("whole");
  command->add_option("--joint-compatibility", options.jointCompatibility,
                      "hybrid one-at-a-time: chi-square confidence of the joint compatibility test")
      ->check(CLI::Range(1e-9, 1.0 - 1e-12))
      ->capture_default_str();
  command->add_option("--max-components", options.maxComponents,
                      "hybrid: keep at most N components, each a copy of its factor graph (0: no cap)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--max-candidates", options.maxCandidates,
                      "hybrid: candidate associations a step may hold; past it whole branching goes one detection "
                      "at a time")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--max-memory", options.maxMemoryMiB,
                      "hybrid: MiB the components' smoothers may hold; past it a step keeps fewer components")
      ->check(CLI::Range(1e-3, 1e9))
      ->capture_default_str();
  command->add_flag("--no-visibility{false}", options.visibility,
                    "hybrid: sampled weights without the visibility model");
}

}  // namespace semslam::cli
