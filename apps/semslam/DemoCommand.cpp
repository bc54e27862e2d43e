// semslam demo --out DIR: paper B's mm-nh (max-mixtures with a null hypothesis) on a small built-in semantic log
// with ambiguous association, beside the same pipeline given the true associations (run/Demo.h); prints one line
// per method and writes the log and both run folders, which python/plot_run.py draws (`make demo`).

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "OptionValidators.h"
#include "semslam/run/Demo.h"

namespace semslam::cli {

namespace {

struct DemoOptions {
  std::string out = "demo";
  std::uint64_t seed = 1;
  bool overwrite = false;
};

void printRun(const char* label, const MethodRun& run) {
  const RunMetrics& m = run.evaluation.metrics;
  std::printf("%-6s ATE %.3f m, DA accuracy %.3f, landmarks %lld (true %lld), time %.2f s\n", label, m.ateRmse,
              m.daAccuracy, m.landmarksEstimated.value_or(0), m.landmarksTrue.value_or(0), run.result.timeSeconds);
}

void run(const DemoOptions& options) {
  const DemoRun demo = runDemo(options.out, options.seed, options.overwrite);
  std::size_t detections = 0, clutter = 0;
  for (const TimeStep& step : demo.log.steps) {
    detections += step.detections.size();
    for (const Detection& detection : step.detections) clutter += detection.truthId == kNotALandmark ? 1 : 0;
  }
  std::printf("demo: %zu steps, %zu landmarks of %d classes, %zu detections (%zu clutter), seed %llu\n",
              demo.log.steps.size(), demo.log.header.landmarkTruth.size(), demo.log.header.classes, detections,
              clutter, static_cast<unsigned long long>(options.seed));
  printRun("mm-nh:", demo.maxMixture);
  printRun("known:", demo.known);
  std::printf("wrote %s, the mm-nh run folder %s and the known run folder %s/known\n", demo.logPath.c_str(),
              options.out.c_str(), options.out.c_str());
}

}  // namespace

void addDemoCommand(CLI::App& app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* command = app.add_subcommand(
      "demo", "Paper B's mm-nh on a small built-in semantic log with ambiguous association (and known beside it)");
  command->add_option("--out", options->out, "output folder")->capture_default_str();
  command->add_option("--seed", options->seed, "seed of the built-in log")
      ->check(unsignedInteger64())
      ->capture_default_str();
  command->add_flag("--overwrite", options->overwrite, "replace an existing non-empty --out folder whole");
  command->callback([options]() { run(*options); });
}

}  // namespace semslam::cli
