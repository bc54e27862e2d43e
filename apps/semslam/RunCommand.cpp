// semslam run --method M --in LOG --out DIR: one method over one measurement log, scored against its truth.
//
//   known | ml | gpda | mm | mm-nh   paper B's pipeline (src/semslam/slam/SemanticSlam.h, docs/max-mixtures.md)
//
// DIR gets metrics.json (docs/metrics.md) and the run folder (src/semslam/io/RunFolder.h): trajectory.tum,
// truth.tum, landmarks.csv, landmarks_truth.csv, covariances.csv, associations.csv. A one-line summary goes to
// standard output.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "Commands.h"
#include "semslam/eval/RunMetrics.h"
#include "semslam/io/InputError.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/slam/SemanticSlamRun.h"
#include "semslam/solve/BatchSmoother.h"

namespace semslam::cli {

namespace {

struct RunArguments {
  std::string method = "mm-nh";
  std::string in;
  std::string out;
  SemanticSlamOptions slam;
  bool noCovariances = false;
};

void printSummary(const std::string& method, const SemanticSlamRun& run) {
  const RunMetrics& m = run.evaluation.metrics;
  std::printf("%s: ATE %.4f m, DA accuracy %.4f, landmarks %lld (true %lld), time %.2f s\n", method.c_str(),
              m.ateRmse, m.daAccuracy, m.landmarksEstimated.value_or(0), m.landmarksTrue.value_or(0),
              run.result.timeSeconds);
}

void run(const RunArguments& arguments) {
  SemanticSlamRunOptions options;
  options.slam = arguments.slam;
  try {
    options.slam.strategy = parseStrategy(arguments.method);
  } catch (const std::invalid_argument& error) {
    throw InputError("--method", 0, error.what());
  }
  options.poseCovariances = !arguments.noCovariances;
  const MeasurementLog log = readMeasurementLog(arguments.in);
  SemanticSlamRun result;
  try {
    result = runSemanticSlam(log, options);
  } catch (const std::invalid_argument& error) {
    throw InputError(arguments.in, 0, error.what());
  }
  std::filesystem::create_directories(arguments.out);
  writeRunFolder(arguments.out, result.output);
  writeRunMetrics((std::filesystem::path(arguments.out) / "metrics.json").string(), result.evaluation.metrics);
  printSummary(arguments.method, result);
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto arguments = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand("run", "run one SLAM method over a measurement log and score it");
  command->add_option("--method", arguments->method, "known, ml, gpda, mm or mm-nh")
      ->check(CLI::IsMember({"known", "ml", "gpda", "mm", "mm-nh"}))
      ->capture_default_str();
  command->add_option("--in", arguments->in, "measurement log (docs/measurement-log.md)")->required();
  command->add_option("--out", arguments->out, "output folder")->required();
  command->add_option("--gate", arguments->slam.gateConfidence, "chi-square gate confidence (paper B: 0.9)")
      ->check(CLI::Range(1e-9, 1.0 - 1e-12))
      ->capture_default_str();
  command->add_option("--null-weight", arguments->slam.nullWeight, "mm-nh: null-hypothesis weight")
      ->check(CLI::Range(1e-9, 1.0 - 1e-9))
      ->capture_default_str();
  command->add_option("--null-sigma-scale", arguments->slam.nullSigmaScale,
                      "mm-nh: null hypothesis's standard deviations over the detection's")
      ->check(CLI::Range(1.0, 1e9))
      ->capture_default_str();
  command->add_option("--em-window", arguments->slam.emWindow, "gpda: steps each E-step re-weights")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--em-iterations", arguments->slam.emIterations, "gpda: E/M rounds per step")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command->add_flag("--no-covariances", arguments->noCovariances,
                    "skip the marginal covariance of every pose (no NEES, no ellipses; faster)");
  command->callback([arguments]() { run(*arguments); });
}

}  // namespace semslam::cli
