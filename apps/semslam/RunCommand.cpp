// semslam run --method M --in LOG --out DIR: run one estimation method on a measurement log and write its run
// folder (metrics.json, trajectory.tum, ...). Methods: hybrid, hybrid-geometric (paper A's hybrid belief, with and
// without the classifier model; src/semslam/hybrid, docs/hybrid-belief.md).

#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "semslam/hybrid/HybridRunFolder.h"
#include "semslam/io/InputError.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam::cli {
namespace {

struct RunOptions {
  std::string method;
  std::string in;
  std::string out;
  std::uint64_t seed = 1;
  int samples = 1000;
  std::string weights = "sampled";
  double pruneRatio = 150.0;
  double gateRatio = 1e5;
  std::string branching = "whole";
  double jointCompatibility = 0.999;
  int maxComponents = 0;
  bool noVisibility = false;
};

HybridOptions hybridOptions(const RunOptions& o) {
  HybridOptions h;
  h.useSemantics = o.method == "hybrid";
  h.weights = o.weights == "analytic" ? WeightMethod::Analytic : WeightMethod::Sampled;
  h.samples = o.samples;
  h.pruneRatio = o.pruneRatio;
  h.gateRatio = o.gateRatio;
  h.branching = o.branching == "one-at-a-time" ? Branching::OneDetectionAtATime : Branching::WholeAssociation;
  h.jointCompatibility = o.jointCompatibility;
  h.maxComponents = o.maxComponents;
  h.visibility = !o.noVisibility;
  h.seed = o.seed;
  return h;
}

void run(const RunOptions& options) {
  const MeasurementLog log = readMeasurementLog(options.in);
  const HybridRunOutput output = runHybrid(log, hybridOptions(options), [](int done, int total) {
    std::fprintf(stderr, "\rstep %d/%d", done, total);
    if (done == total) std::fprintf(stderr, "\n");
  });
  const RunMetrics metrics = writeHybridRunFolder(options.out, log, output);
  std::printf("%s on %s: %zu steps, %lld components at the end, entropy %.4g, err_wmax %.4g m, time %.3f s\n",
              metrics.method.c_str(), options.in.c_str(), log.steps.size(), metrics.components.value_or(0),
              metrics.entropy, metrics.errWmax, metrics.timeSeconds);
  std::printf("wrote %s/{metrics.json,trajectory.tum,hypotheses.jsonl}\n", options.out.c_str());
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* command = app.add_subcommand("run", "run an estimation method on a measurement log");
  command->add_option("--method", options->method, "hybrid or hybrid-geometric")
      ->required()
      ->check(CLI::IsMember({"hybrid", "hybrid-geometric"}));
  command->add_option("--in", options->in, "the measurement log (JSON lines)")->required()->check(CLI::ExistingFile);
  command->add_option("--out", options->out, "the run folder to write")->required();
  command->add_option("--seed", options->seed, "seed of the Monte Carlo draws")->capture_default_str();
  command->add_option("--samples", options->samples, "samples per weight (A, eq. 16)")
      ->check(CLI::Range(2, 100000000))
      ->capture_default_str();
  command->add_option("--weights", options->weights, "sampled (A, eq. 16) or analytic (linearised)")
      ->check(CLI::IsMember({"sampled", "analytic"}))
      ->capture_default_str();
  command->add_option("--prune-ratio", options->pruneRatio, "prune w < w_max / ratio (<= 1: no pruning)")
      ->capture_default_str();
  command->add_option("--gate-ratio", options->gateRatio,
                      "skip sampling when the linearised weight < w_max / ratio (<= 1: no gate)")
      ->capture_default_str();
  command->add_option("--branching", options->branching, "whole (every association of a step) or one-at-a-time")
      ->check(CLI::IsMember({"whole", "one-at-a-time"}))
      ->capture_default_str();
  command->add_option("--joint-compatibility", options->jointCompatibility,
                      "one-at-a-time: chi-square confidence of the joint compatibility test")
      ->check(CLI::Range(1e-9, 1.0 - 1e-12))
      ->capture_default_str();
  command->add_option("--max-components", options->maxComponents, "keep at most N components (0: no cap)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_flag("--no-visibility", options->noVisibility, "sampled weights without the visibility model");
  command->callback([options] { run(*options); });
}

}  // namespace semslam::cli
