// semslam run --method M --in LOG --out DIR: one estimation method over one measurement log, scored against its
// truth. DIR gets metrics.json (docs/metrics.md) and the run folder (src/semslam/io/RunFolder.h).
//
//   known | ml | gpda | mm | mm-nh   paper B's pipeline (src/semslam/slam, docs/max-mixtures.md): trajectory.tum,
//                                    truth.tum, landmarks.csv, landmarks_truth.csv, covariances.csv,
//                                    associations.csv
//   hybrid | hybrid-geometric        paper A's hybrid belief with and without the classifier model
//                                    (src/semslam/hybrid, docs/hybrid-belief.md): trajectory.tum, hypotheses.jsonl
// A one-line summary goes to standard output.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "Commands.h"
#include "semslam/eval/RunMetrics.h"
#include "semslam/hybrid/HybridRunFolder.h"
#include "semslam/io/InputError.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/slam/SemanticSlamRun.h"
#include "semslam/study/ProgressBar.h"
#include "semslam/solve/SmootherFactory.h"

namespace semslam::cli {
namespace {

struct HybridArguments {
  std::uint64_t seed = 1;
  int samples = 1000;
  std::string weights = "sampled";
  int importanceIterations = 1;
  double pruneRatio = 150.0;
  double gateRatio = 1e5;
  std::string branching = "whole";
  double jointCompatibility = 0.999;
  int maxComponents = 0;
  bool noVisibility = false;
};

struct RunArguments {
  std::string method = "mm-nh";
  std::string smoother;  // empty: the method's default (incremental for paper B, batch LM for the hybrid belief)
  std::string in;
  std::string out;
  SemanticSlamOptions slam;
  bool noCovariances = false;
  HybridArguments hybrid;
};

bool isHybrid(const std::string& method) { return method == "hybrid" || method == "hybrid-geometric"; }

HybridOptions hybridOptions(const RunArguments& arguments) {
  const HybridArguments& o = arguments.hybrid;
  HybridOptions h;
  h.useSemantics = arguments.method == "hybrid";
  h.weights = parseWeightMethod(o.weights);
  h.samples = o.samples;
  h.importanceIterations = o.importanceIterations;
  h.pruneRatio = o.pruneRatio;
  h.gateRatio = o.gateRatio;
  h.branching = o.branching == "one-at-a-time" ? Branching::OneDetectionAtATime : Branching::WholeAssociation;
  h.jointCompatibility = o.jointCompatibility;
  h.maxComponents = o.maxComponents;
  h.visibility = !o.noVisibility;
  h.seed = o.seed;
  if (!arguments.smoother.empty() && parseSmootherKind(arguments.smoother) == SmootherKind::Incremental) {
    h.smootherFactory = smootherFactory(SmootherKind::Incremental);
  }
  return h;
}

void runHybridMethod(const RunArguments& arguments, const MeasurementLog& log) {
  ProgressBar progress("run " + arguments.method, static_cast<int>(log.steps.size()), ProgressBar::Mode::Always);
  const HybridRunOutput output =
      runHybrid(log, hybridOptions(arguments), [&progress](int done, int) { progress.update(done); });
  const RunMetrics metrics = writeHybridRunFolder(arguments.out, log, output);
  std::printf("%s on %s: %zu steps, %lld components at the end, entropy %.4g, err_wmax %.4g m, time %.3f s\n",
              metrics.method.c_str(), arguments.in.c_str(), log.steps.size(), metrics.components.value_or(0),
              metrics.entropy, metrics.errWmax, metrics.timeSeconds);
}

void runSemanticSlamMethod(const RunArguments& arguments, const MeasurementLog& log) {
  SemanticSlamRunOptions options;
  options.slam = arguments.slam;
  options.slam.strategy = parseStrategy(arguments.method);
  if (!arguments.smoother.empty()) options.slam.smoother = smootherFactory(parseSmootherKind(arguments.smoother));
  options.poseCovariances = !arguments.noCovariances;
  SemanticSlamRun result;
  try {
    result = runSemanticSlam(log, options);
  } catch (const std::invalid_argument& error) {
    throw InputError(arguments.in, 0, error.what());
  }
  std::filesystem::create_directories(arguments.out);
  writeRunFolder(arguments.out, result.output);
  writeRunMetrics((std::filesystem::path(arguments.out) / "metrics.json").string(), result.evaluation.metrics);
  const RunMetrics& m = result.evaluation.metrics;
  std::printf("%s: ATE %.4f m, DA accuracy %.4f, landmarks %lld (true %lld), time %.2f s\n", arguments.method.c_str(),
              m.ateRmse, m.daAccuracy, m.landmarksEstimated.value_or(0), m.landmarksTrue.value_or(0),
              result.result.timeSeconds);
}

void addSemanticSlamOptions(CLI::App* command, RunArguments& arguments) {
  command->add_option("--gate", arguments.slam.gateConfidence, "chi-square gate confidence (paper B: 0.9)")
      ->check(CLI::Range(1e-9, 1.0 - 1e-12))
      ->capture_default_str();
  command->add_option("--null-weight", arguments.slam.nullWeight, "mm-nh: null-hypothesis weight")
      ->check(CLI::Range(1e-9, 1.0 - 1e-9))
      ->capture_default_str();
  command->add_option("--null-sigma-scale", arguments.slam.nullSigmaScale,
                      "mm-nh: null hypothesis's standard deviations over the detection's")
      ->check(CLI::Range(1.0, 1e9))
      ->capture_default_str();
  command->add_option("--em-window", arguments.slam.emWindow, "gpda: steps each E-step re-weights")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--em-iterations", arguments.slam.emIterations, "gpda: E/M rounds per step")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command->add_flag("--no-warm-start{false}", arguments.slam.warmStart,
                    "mm, mm-nh: choose mixture components at the odometry prediction (docs/max-mixtures.md)");
  command->add_flag("--no-covariances", arguments.noCovariances,
                    "skip the marginal covariance of every pose (no NEES, no ellipses; faster)");
}

void addHybridOptions(CLI::App* command, HybridArguments& hybrid) {
  command->add_option("--seed", hybrid.seed, "hybrid: seed of the Monte Carlo draws")->capture_default_str();
  command->add_option("--samples", hybrid.samples, "hybrid: samples per weight (A, eq. 16)")
      ->check(CLI::Range(2, 100000000))
      ->capture_default_str();
  command->add_option("--weights", hybrid.weights, "hybrid: sampled (A, eq. 16-17, plain Monte Carlo), importance (linearised-posterior proposal) or analytic (linearised)")
      ->check(CLI::IsMember({"sampled", "importance", "analytic"}))
      ->capture_default_str();
  command->add_option("--importance-iterations", hybrid.importanceIterations,
                      "hybrid: importance weights' proposal linearisations (1: at the mean; > 1: iterated)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  command->add_option("--prune-ratio", hybrid.pruneRatio, "hybrid: prune w < w_max / ratio (<= 1: no pruning)")
      ->capture_default_str();
  command->add_option("--gate-ratio", hybrid.gateRatio,
                      "hybrid: skip sampling when the linearised weight < w_max / ratio (<= 1: no gate)")
      ->capture_default_str();
  command->add_option("--branching", hybrid.branching, "hybrid: whole (every association of a step) or one-at-a-time")
      ->check(CLI::IsMember({"whole", "one-at-a-time"}))
      ->capture_default_str();
  command->add_option("--joint-compatibility", hybrid.jointCompatibility,
                      "hybrid one-at-a-time: chi-square confidence of the joint compatibility test")
      ->check(CLI::Range(1e-9, 1.0 - 1e-12))
      ->capture_default_str();
  command->add_option("--max-components", hybrid.maxComponents, "hybrid: keep at most N components (0: no cap)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_flag("--no-visibility", hybrid.noVisibility, "hybrid: sampled weights without the visibility model");
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto arguments = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand("run", "run one estimation method over a measurement log and score it");
  command->add_option("--method", arguments->method, "known, ml, gpda, mm, mm-nh, hybrid or hybrid-geometric")
      ->check(CLI::IsMember({"known", "ml", "gpda", "mm", "mm-nh", "hybrid", "hybrid-geometric"}))
      ->capture_default_str();
  command->add_option("--in", arguments->in, "measurement log (docs/measurement-log.md)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", arguments->out, "output folder")->required();
  command->add_option("--smoother", arguments->smoother,
                      "back end: incremental or batch (default: incremental for known..mm-nh, batch for hybrid)")
      ->check(CLI::IsMember({"incremental", "batch"}));
  addSemanticSlamOptions(command, *arguments);
  addHybridOptions(command, arguments->hybrid);
  command->callback([arguments]() {
    const MeasurementLog log = readMeasurementLog(arguments->in);
    if (isHybrid(arguments->method)) {
      runHybridMethod(*arguments, log);
    } else {
      runSemanticSlamMethod(*arguments, log);
    }
  });
}

}  // namespace semslam::cli
