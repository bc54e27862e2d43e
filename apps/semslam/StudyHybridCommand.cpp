// semslam study hybrid: paper A's statistical study (sec. V, Fig. 5) on aliased2d, with and without the classifier
// model, over tracks and alphas (src/semslam/hybrid/HybridStudy.h).


#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "semslam/hybrid/HybridStudy.h"
#include "semslam/io/InputError.h"
#include "semslam/sim/ScenarioFile.h"
#include "semslam/study/ProgressBar.h"

namespace semslam::cli {
namespace {

struct StudyHybridOptions {
  std::string scenario;
  int tracks = 50;
  int steps = 10;
  std::vector<double> alphas{0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
  std::uint64_t seed = 1;
  int samples = 1000;
  std::string weights = "sampled";
  int importanceIterations = 1;
  double pruneRatio = 150.0;
  double gateRatio = 1e5;
  int maxComponents = 0;
  int threads = 2;
  std::string out;
};

void runStudy(const StudyHybridOptions& o) {
  HybridStudyOptions options;
  if (!o.scenario.empty()) options.scenario = readAliased2dScenario(o.scenario);
  options.tracks = o.tracks;
  options.steps = o.steps;
  options.alphas = o.alphas;
  options.seed = o.seed;
  options.threads = o.threads;
  options.hybrid.samples = o.samples;
  options.hybrid.weights = parseWeightMethod(o.weights);
  options.hybrid.importanceIterations = o.importanceIterations;
  options.hybrid.pruneRatio = o.pruneRatio;
  options.hybrid.gateRatio = o.gateRatio;
  options.hybrid.maxComponents = o.maxComponents;
  for (double a : o.alphas) {
    if (!(a >= 0.0 && a <= 1.0)) throw InputError("--alpha: every alpha must be in [0, 1]");
  }
  const auto start = std::chrono::steady_clock::now();
  ProgressBar progress("study hybrid", o.tracks * static_cast<int>(o.alphas.size()) * 2, ProgressBar::Mode::Always);
  const std::vector<HybridStudyRow> rows =
      runHybridStudy(options, [&progress](int done, int) { progress.update(done); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeHybridStudy(o.out, rows);
  std::printf("hybrid study: %zu runs (%d tracks x %zu alphas x 2 models, %d steps) in %.1f s on %d threads\n",
              rows.size(), o.tracks, o.alphas.size(), o.steps, seconds, o.threads);
  std::printf("wrote %s/{runs.csv,summary.csv,nees.csv}\n", o.out.c_str());
}

}  // namespace

void addStudyHybridCommand(CLI::App& study) {
  auto o = std::make_shared<StudyHybridOptions>();
  CLI::App* hybrid = study.add_subcommand("hybrid", "paper A's study: hybrid belief with and without the classifier");
  hybrid->add_option("--scenario", o->scenario, "aliased2d scenario JSON (default: the built-in layout)")
      ->check(CLI::ExistingFile);
  hybrid->add_option("--tracks", o->tracks, "tracks per alpha")->check(CLI::Range(1, 100000))->capture_default_str();
  hybrid->add_option("--steps", o->steps, "steps per track")->check(CLI::Range(1, 100000))->capture_default_str();
  hybrid->add_option("--alpha", o->alphas, "classifier viewpoint dependencies, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  hybrid->add_option("--seed", o->seed, "seed of tracks and draws")->capture_default_str();
  hybrid->add_option("--samples", o->samples, "samples per weight")->check(CLI::Range(2, 100000000))->capture_default_str();
  hybrid->add_option("--weights", o->weights, "sampled (A, eq. 17), importance or analytic")
      ->check(CLI::IsMember({"sampled", "importance", "analytic"}))
      ->capture_default_str();
  hybrid->add_option("--importance-iterations", o->importanceIterations,
                     "importance weights: linearisations of the proposal (1: at the mean; > 1: iterated update)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  hybrid->add_option("--prune-ratio", o->pruneRatio, "prune w < w_max / ratio")->capture_default_str();
  hybrid->add_option("--gate-ratio", o->gateRatio, "gate before sampling at w_max / ratio")->capture_default_str();
  hybrid->add_option("--max-components", o->maxComponents, "cap on components (0: none)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  hybrid->add_option("--threads", o->threads, "worker threads")->check(CLI::Range(1, 64))->capture_default_str();
  hybrid->add_option("--out", o->out, "output folder")->required();
  hybrid->callback([o] { runStudy(*o); });
}

}  // namespace semslam::cli
