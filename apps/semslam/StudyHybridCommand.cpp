// semslam study hybrid: paper A's statistical study (sec. V, Fig. 5) on aliased2d, with and without the classifier
// model, over tracks and alphas (src/semslam/study/HybridStudy.h).

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "MethodOptions.h"
#include "semslam/study/HybridStudy.h"
#include "semslam/core/InputError.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/core/ProgressBar.h"

namespace semslam::cli {
namespace {

struct StudyHybridArguments {
  std::string scenario;  ///< a scenario file; empty: the built-in layout
  std::string out;
  bool quiet = false;
  HybridStudyOptions options;
};

void runStudy(StudyHybridArguments arguments) {
  HybridStudyOptions& options = arguments.options;
  if (!arguments.scenario.empty()) options.scenario = readAliased2dScenario(arguments.scenario);
  for (double a : options.alphas) {
    if (!(a >= 0.0 && a <= 1.0)) throw InputError("--alpha: every alpha must be in [0, 1]");
  }
  const auto start = std::chrono::steady_clock::now();
  ProgressBar progress("study hybrid", options.tracks * static_cast<int>(options.alphas.size()) * 2,
                       arguments.quiet);
  const std::vector<HybridStudyRow> rows =
      runHybridStudy(options, [&progress](int done, int) { progress.update(done); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeHybridStudy(arguments.out, rows);
  std::printf("hybrid study: %zu runs (%d tracks x %zu alphas x 2 models, %d steps) in %.1f s on %d threads\n",
              rows.size(), options.tracks, options.alphas.size(), options.steps, seconds, options.threads);
  std::printf("wrote %s/{runs.csv,summary.csv,nees.csv}\n", arguments.out.c_str());
}

}  // namespace

void addStudyHybridCommand(CLI::App& study) {
  auto arguments = std::make_shared<StudyHybridArguments>();
  HybridStudyOptions& o = arguments->options;
  CLI::App* hybrid = study.add_subcommand("hybrid", "paper A's study: hybrid belief with and without the classifier");
  hybrid->add_option("--scenario", arguments->scenario, "aliased2d scenario JSON (default: the built-in layout)")
      ->check(CLI::ExistingFile);
  hybrid->add_option("--tracks", o.tracks, "tracks per alpha")->check(CLI::Range(1, 100000))->capture_default_str();
  hybrid->add_option("--steps", o.steps, "steps per track")->check(CLI::Range(1, 100000))->capture_default_str();
  hybrid->add_option("--alpha", o.alphas, "classifier viewpoint dependencies, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  hybrid->add_option("--seed", o.seed, "seed of tracks and draws")->capture_default_str();
  addHybridOptions(hybrid, o.hybrid);
  hybrid->add_option("--threads", o.threads, "worker threads")->check(CLI::Range(1, 64))->capture_default_str();
  hybrid->add_option("--out", arguments->out, "output folder")->required();
  hybrid->add_flag("--quiet", arguments->quiet, "no progress line");
  hybrid->callback([arguments] { runStudy(*arguments); });
}

}  // namespace semslam::cli
