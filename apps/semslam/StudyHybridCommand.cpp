// semslam study hybrid: paper A's statistical study (sec. V, Fig. 5) on aliased2d, with and without the classifier
// model, over layouts (generated, --layouts/--layout-seed, or scenario files, --scenario), tracks and alphas
// (src/semslam/study/HybridStudy.h). Under mpirun the runs are spread over the ranks (DistributedRuns.h); rank 0
// writes the folder, the same bytes for any number of ranks and threads but timings.csv (docs/studies.md).

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Commands.h"
#include "DistributedRuns.h"
#include "MethodOptions.h"
#include "OptionValidators.h"
#include "semslam/core/InputError.h"
#include "semslam/core/ProgressBar.h"
#include "semslam/io/OutputTarget.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/io/StagedFolder.h"
#include "semslam/study/HybridStudy.h"
#include "semslam/study/StudyRowBytes.h"

namespace semslam::cli {
namespace {

struct StudyHybridArguments {
  std::vector<std::string> scenarios;  ///< scenario files, a layout each; empty: generated layouts
  int layouts = 10;                    ///< generated layouts (without --scenario)
  std::uint64_t layoutSeed = 1;        ///< the first generated layout's seed
  std::string poseMean;                ///< "start" | "sampled": replaces every layout's pose prior mean; empty: kept
  std::string out;
  bool overwrite = false;
  bool quiet = false;
  HybridStudyOptions options;
};

void runStudy(StudyHybridArguments arguments) {
  HybridStudyOptions& options = arguments.options;
  if (arguments.scenarios.empty()) {
    options.layouts = generatedHybridStudyLayouts(arguments.layoutSeed, arguments.layouts);
  } else {
    options.layouts.clear();
    for (const std::string& path : arguments.scenarios) options.layouts.push_back(readAliased2dScenario(path));
  }
  if (!arguments.poseMean.empty()) {
    for (Aliased2dScenario& layout : options.layouts) {
      layout.priors.poseMean = arguments.poseMean == "start" ? PoseMean::Start : PoseMean::Sampled;
    }
  }
  for (double a : options.alphas) {
    if (!(a >= 0.0 && a <= 1.0)) throw InputError("--alpha: every alpha must be in [0, 1]");
  }
  std::vector<HybridStudyRun> runs;
  try {
    runs = hybridStudyRuns(options);
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
  // The rank that writes checks and stages the folder before the work and renames it into place whole after it
  // (io/StagedFolder.h); under mpirun a refusal there ends the job.
  std::optional<StagedFolder> folder;
  if (isGatheringRank()) {
    for (const std::string& path : arguments.scenarios) requireOutputSparesInput(arguments.out, path, "--out");
    folder.emplace(arguments.out, arguments.overwrite);
  }
  // Only the rank that writes draws progress (a helper rank's bar is never drawn).
  ProgressBar progress("study hybrid", static_cast<int>(runs.size()), arguments.quiet || !isGatheringRank());
  const DistributedResults distributed = runDistributed(
      runs.size(), options.threads,
      [&](std::size_t i) { return encodeHybridStudyRow(runHybridStudyRun(options, runs[i])); },
      [&progress](int done, int) { progress.update(done); });
  if (!distributed.gathered) return;
  std::vector<HybridStudyRow> rows;
  for (const std::string& bytes : distributed.results) rows.push_back(decodeHybridStudyRow(bytes));
  writeHybridStudy(folder->path(), options, rows, distributed.layout);
  folder->commit();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].error.empty() && !arguments.quiet) {
      // i counts the runs made: a track's geometric run is one, at the first alpha, reported at every alpha.
      std::fprintf(stderr, "semslam: warning: run %zu (layout %d, alpha %g, track %d, %s) failed: %s\n", i,
                   rows[i].layout, rows[i].alpha, rows[i].track, rows[i].model.c_str(), rows[i].error.c_str());
    }
  }
  std::printf("hybrid study: %zu runs (%zu layouts x %d tracks x (%zu alphas with the classifier + 1 geometric), "
              "%d steps, %d failed) in %.1f s on %d rank(s) x %d threads\n",
              rows.size(), options.layouts.size(), options.tracks, options.alphas.size(), options.steps,
              failedHybridRuns(rows), distributed.layout.wallSeconds, distributed.layout.ranks, options.threads);
  std::printf("wrote %s/{runs.csv,summary.csv,nees.csv,timings.csv,layouts.csv,layouts/}\n", arguments.out.c_str());
}

}  // namespace

void addStudyHybridCommand(CLI::App& study) {
  auto arguments = std::make_shared<StudyHybridArguments>();
  HybridStudyOptions& o = arguments->options;
  CLI::App* hybrid = study.add_subcommand("hybrid", "paper A's study: hybrid belief with and without the classifier");
  CLI::Option* scenario =
      hybrid
          ->add_option("--scenario", arguments->scenarios,
                       "aliased2d scenario JSON files, one layout each (default: generated layouts)")
          ->check(CLI::ExistingFile);
  hybrid->add_option("--layouts", arguments->layouts, "generated layouts (sim/Aliased2dLayout.h)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str()
      ->excludes(scenario);
  hybrid->add_option("--layout-seed", arguments->layoutSeed, "seed of the first generated layout (then +1, +2, ...)")
      ->check(unsignedInteger64())
      ->capture_default_str()
      ->excludes(scenario);
  hybrid->add_option("--pose-mean", arguments->poseMean,
                     "the estimator's prior mean of the first pose in every layout: start (paper A: the true start) "
                     "or sampled (drawn from the prior; docs/simulators.md); default: each layout's own")
      ->check(CLI::IsMember({"start", "sampled"}));
  hybrid->add_option("--tracks", o.tracks, "tracks per layout and alpha")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  hybrid->add_option("--steps", o.steps, "steps per track")->check(CLI::Range(1, 100000))->capture_default_str();
  hybrid->add_option("--alpha", o.alphas, "classifier viewpoint dependencies, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  hybrid->add_option("--seed", o.seed, "seed of tracks and draws")->check(unsignedInteger64())->capture_default_str();
  addHybridOptions(hybrid, o.hybrid);
  hybrid->add_option("--threads", o.threads, "worker threads")->check(CLI::Range(1, 64))->capture_default_str();
  hybrid->add_option("--out", arguments->out, "output folder")->required();
  hybrid->add_flag("--overwrite", arguments->overwrite, "replace an existing non-empty --out folder whole");
  hybrid->add_flag("--quiet", arguments->quiet, "no progress line");
  hybrid->callback([arguments] { runStudy(*arguments); });
}

}  // namespace semslam::cli
