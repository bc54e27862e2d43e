// semslam study robustness: paper B's robustness study (sec. V-A, Fig. 3) on one log (docs/robustness-study.md).
//
//   semslam study robustness --log LOG --methods known,ml,gpda,mm,mm-nh --odom-noise-scale 0,1,2,5,10
//       --misclassification 0,0.1,0.2,0.3,0.5 --seeds 10 --out DIR
//
// Two one-axis sweeps (noise scale at misclassification 0.1; misclassification at noise scale 1), every cell's
// perturbed log shared by all methods, cells spread over --threads worker threads (and over the ranks under mpirun:
// DistributedRuns.h, docs/studies.md). DIR gets robustness.csv (one row per axis, level, seed and method),
// robustness_summary.csv (mean and 95% t-interval per axis, level and method), study.json (the settings) and
// timings.csv (run times, layout, wall time), written by study/RobustnessStudyFolder.h; paper B's options are
// the shared block of MethodOptions.h (--gate, --null-weight, ..., --no-warm-start); python/plot_robustness.py DIR
// draws the box plots.

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "Commands.h"
#include "DistributedRuns.h"
#include "MethodOptions.h"
#include "OptionValidators.h"
#include "semslam/core/InputError.h"
#include "semslam/core/ProgressBar.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/OutputTarget.h"
#include "semslam/io/StagedFolder.h"
#include "semslam/slam/SemanticSlamSmoother.h"
#include "semslam/solve/SmootherFactory.h"
#include "semslam/study/RobustnessStudy.h"
#include "semslam/study/RobustnessStudyFolder.h"
#include "semslam/study/StudyRowBytes.h"

namespace semslam::cli {

namespace {

struct RobustnessArguments {
  std::string log;
  std::string out;
  bool overwrite = false;
  std::string methods = "known,ml,gpda,mm,mm-nh";
  std::string noiseScales = "0,1,2,5,10";
  std::string rates = "0,0.1,0.2,0.3,0.5";
  int seeds = 10;
  std::uint64_t baseSeed = 0;
  int threads = 2;
  int maxSteps = 0;
  std::string smoother = "incremental";
  SemanticSlamOptions slam;  ///< paper B's options (MethodOptions.h); the back end is --smoother
  double modelFloor = 0.0;
  bool quiet = false;
  bool progress = false;
};

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    if (first == std::string::npos) continue;
    items.push_back(item.substr(first, last - first + 1));
  }
  return items;
}

std::vector<double> parseLevels(const std::string& text, const std::string& option) {
  std::vector<double> levels;
  for (const std::string& item : splitList(text)) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !std::isfinite(value)) throw InputError(option + ": '" + item + "' is not a number");
    levels.push_back(value);
  }
  if (levels.empty()) throw InputError(option + ": give at least one level (comma-separated)");
  return levels;
}

void runRobustness(const RobustnessArguments& arguments) {
  RobustnessStudyOptions options;
  options.methods.clear();
  for (const std::string& name : splitList(arguments.methods)) {
    try {
      options.methods.push_back(parseStrategy(name));
    } catch (const std::invalid_argument& error) {
      throw InputError("--methods", 0, error.what());
    }
  }
  if (options.methods.empty()) throw InputError("--methods: give at least one method (comma-separated)");
  options.noiseScales = parseLevels(arguments.noiseScales, "--odom-noise-scale");
  for (double s : options.noiseScales) {
    if (s < 0.0) throw InputError("--odom-noise-scale: " + std::to_string(s) + " is negative");
  }
  options.misclassificationRates = parseLevels(arguments.rates, "--misclassification");
  for (double p : options.misclassificationRates) {
    if (!(p >= 0.0 && p < 1.0)) throw InputError("--misclassification: " + std::to_string(p) + " is not in [0, 1)");
  }
  options.seeds = arguments.seeds;
  options.baseSeed = arguments.baseSeed;
  options.threads = arguments.threads;
  options.maxSteps = arguments.maxSteps;
  options.slam = arguments.slam;
  options.slam.smoother = smootherFactory(parseSmootherKind(arguments.smoother), {}, semanticSlamSmootherParams());
  options.modelMisclassificationFloor = arguments.modelFloor;
  try {
    validateRobustnessOptions(options);
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }

  // The rank that writes checks and stages the folder before the work and renames it into place whole after it
  // (io/StagedFolder.h); under mpirun a refusal there ends the job.
  std::optional<StagedFolder> folder;
  if (isGatheringRank()) {
    requireOutputSparesInput(arguments.out, arguments.log, "--out");
    folder.emplace(arguments.out, arguments.overwrite);
  }
  const MeasurementLog log = readMeasurementLog(arguments.log);
  const std::vector<RobustnessCell> cells = robustnessCells(options);
  const int methods = static_cast<int>(options.methods.size());
  // Progress counts runs; a cell (the unit spread over threads and ranks) is `methods` runs.
  ProgressBar bar("study robustness", static_cast<int>(cells.size()) * methods,
                  arguments.quiet || !isGatheringRank());
  DistributedResults distributed;
  try {
    distributed = runDistributed(
        cells.size(), options.threads,
        [&](std::size_t i) { return encodeRobustnessRows(runRobustnessCell(log, options, cells[i])); },
        [&bar, methods](int done, int) { bar.update(done * methods); });
  } catch (const std::invalid_argument& error) {
    throw InputError(arguments.log, 0, error.what());
  }
  if (!distributed.gathered) return;
  RobustnessStudy study;
  study.layout = distributed.layout;
  for (const std::string& bytes : distributed.results) {
    for (RobustnessRow& row : decodeRobustnessRows(bytes)) study.rows.push_back(std::move(row));
  }

  writeRobustnessStudyFolder(folder->path(), study, options, {arguments.log, arguments.methods, arguments.smoother});
  folder->commit();
  const int failed = failedRobustnessRuns(study.rows);
  int warned = 0;
  for (std::size_t i = 0; i < study.rows.size(); ++i) {
    const RobustnessRow& row = study.rows[i];
    if (row.error.empty() || arguments.quiet || ++warned > 5) continue;
    std::fprintf(stderr, "semslam: warning: run %zu (%s %g seed %d %s) failed: %s\n", i,
                 robustnessAxisName(row.axis).c_str(), row.level, row.seed, row.method.c_str(), row.error.c_str());
  }
  std::printf("study robustness: %zu runs (%d failed) of %s on %s in %.1f s on %d rank(s) x %d threads; wrote "
              "%s/robustness.csv, robustness_summary.csv, study.json, timings.csv\n",
              study.rows.size(), failed, arguments.methods.c_str(), arguments.log.c_str(), study.layout.wallSeconds,
              study.layout.ranks, options.threads, arguments.out.c_str());
}

}  // namespace

void addStudyRobustnessCommand(CLI::App& study) {
  auto a = std::make_shared<RobustnessArguments>();
  CLI::App* command = study.add_subcommand(
      "robustness", "paper B's robustness study: sweeps of odometry noise and misclassification, box plots' data");
  command->add_option("--log", a->log, "measurement log (docs/measurement-log.md)")->required()->check(
      CLI::ExistingFile);
  command->add_option("--out", a->out, "output folder")->required();
  command->add_flag("--overwrite", a->overwrite, "replace an existing non-empty --out folder whole");
  command->add_option("--methods", a->methods, "comma-separated: known, ml, gpda, mm, mm-nh")->capture_default_str();
  command->add_option("--odom-noise-scale", a->noiseScales,
                      "comma-separated odometry noise scales (x 0.02 m, 0.02 m, 0.01 rad per second)")
      ->capture_default_str();
  command->add_option("--misclassification", a->rates, "comma-separated misclassification rates in [0, 1)")
      ->capture_default_str();
  command->add_option("--seeds", a->seeds, "seeds per level")->check(CLI::Range(1, 1000000))->capture_default_str();
  command->add_option("--seed", a->baseSeed, "first perturbation seed (seeds are seed .. seed + seeds - 1)")
      ->check(unsignedInteger64())
      ->capture_default_str();
  command->add_option("--threads", a->threads, "worker threads")->check(CLI::Range(1, 256))->capture_default_str();
  command->add_option("--max-steps", a->maxSteps, "use only the log's first N steps (0: all)")
      ->check(CLI::Range(0, 1000000000))
      ->capture_default_str();
  command->add_option("--smoother", a->smoother, "back end: incremental or batch")
      ->check(CLI::IsMember({"incremental", "batch"}))
      ->capture_default_str();
  addSemanticSlamOptions(command, a->slam);
  command->add_option("--model-floor", a->modelFloor,
                      "the methods' model misclassification rate is max(p, this) (0: the exact rate)")
      ->check(CLI::Range(0.0, 0.5))
      ->capture_default_str();
  command->add_flag("--quiet", a->quiet, "no progress line, no warnings");
  command->add_flag("--progress", a->progress,
                    "accepted for old scripts: progress is shown on and off a terminal unless --quiet");
  command->callback([a]() { runRobustness(*a); });
}

}  // namespace semslam::cli
