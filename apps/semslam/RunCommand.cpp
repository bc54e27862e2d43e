// semslam run --method M --in LOG --out DIR: one estimation method over one measurement log, scored against its
// truth (run/RunMethod.h: runMethod, writeMethodRun). DIR gets metrics.json (docs/metrics.md) and the run folder
// (src/semslam/io/RunFolder.h; hypotheses.jsonl too for the hybrid methods). A one-line summary goes to standard
// output. With --on-known-trajectory the method runs with its poses pinned to the known-association estimate (and
// --pose-error-scale s: moved inside s times its covariance), what association alone could reach on the log
// (run/KnownTrajectoryCeiling.h).

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "Commands.h"
#include "MethodOptions.h"
#include "OptionValidators.h"
#include "semslam/core/InputError.h"
#include "semslam/core/ProgressBar.h"
#include "semslam/hybrid/HybridRun.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/OutputTarget.h"
#include "semslam/io/StagedFolder.h"
#include "semslam/run/KnownTrajectoryCeiling.h"
#include "semslam/run/RunMethod.h"
#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam::cli {
namespace {

struct RunArguments {
  std::string method = "mm-nh";
  std::string smoother;  // empty: the method's default (incremental for paper B, batch LM for the hybrid belief)
  std::string in;
  std::string out;
  bool noCovariances = false;
  bool onKnownTrajectory = false;
  double poseErrorScale = 0.0;
  bool quiet = false;
  bool overwrite = false;
  MethodOptions options;
};

void printSummary(const RunArguments& arguments, const MeasurementLog& log, const MethodRun& run) {
  const RunMetrics& m = run.evaluation.metrics;
  if (isHybrid(run.method)) {
    std::printf("%s on %s: %zu steps, %lld components at the end, entropy %.4g, err_wmax %.4g m, time %.3f s\n",
                m.method.c_str(), arguments.in.c_str(), log.steps.size(), m.components.value_or(0), m.entropy,
                m.errWmax, m.timeSeconds);
    const std::string bounds = describeBoundsThatBound(run.hybridReports, arguments.options.hybrid);
    if (!bounds.empty()) std::fprintf(stderr, "note: %s\n", bounds.c_str());
  } else {
    std::printf("%s: ATE %.4f m, DA accuracy %.4f, landmarks %lld (true %lld), time %.2f s\n",
                arguments.method.c_str(), m.ateRmse, m.daAccuracy, m.landmarksEstimated.value_or(0),
                m.landmarksTrue.value_or(0), run.result.timeSeconds);
  }
}

void run(RunArguments arguments) {
  // The folder is checked and staged before the work, and renamed into place whole after it (io/StagedFolder.h).
  requireOutputSparesInput(arguments.out, arguments.in, "--out");
  StagedFolder folder(arguments.out, arguments.overwrite);
  const MeasurementLog log = readMeasurementLog(arguments.in);
  MethodOptions& options = arguments.options;
  options.method = parseMethod(arguments.method);
  if (!arguments.smoother.empty()) options.smoother = parseSmootherKind(arguments.smoother);
  options.poseCovariances = !arguments.noCovariances;
  // Every method shows its progress per step (core/ProgressBar.h: in place on a terminal, a line every few
  // seconds elsewhere); --quiet silences it.
  ProgressBar progress("run " + arguments.method, static_cast<int>(log.steps.size()), arguments.quiet);
  MethodRun result;
  try {
    if (arguments.onKnownTrajectory) {
      result = runOnKnownTrajectory(log, options, arguments.poseErrorScale,
                                    static_cast<std::uint32_t>(options.hybrid.seed));
    } else {
      result = runMethod(log, options, [&progress](int done, int) { progress.update(done); });
    }
  } catch (const std::invalid_argument& error) {
    throw InputError(arguments.in, 0, error.what());
  } catch (const std::domain_error& error) {  // a geometry the models cannot take (a point at its sensor)
    throw InputError(arguments.in, 0, error.what());
  } catch (const UnconstrainedSystemError& error) {  // the log leaves a variable free: say what would hold it
    throw InputError(arguments.in, 0,
                     std::string(error.what()) +
                         " (In a measurement log the header's initial_pose is the prior on the first pose and "
                         "landmark_priors hold known landmarks; docs/measurement-log.md.)");
  }
  writeMethodRun(folder.path(), result);
  folder.commit();
  printSummary(arguments, log, result);
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto arguments = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand("run", "run one estimation method over a measurement log and score it");
  command->add_option("--method", arguments->method, "known, ml, gpda, mm, mm-nh, hybrid or hybrid-geometric")
      ->check(CLI::IsMember(methodNames()))
      ->capture_default_str();
  command->add_option("--in", arguments->in, "measurement log (docs/measurement-log.md)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", arguments->out, "output folder")->required();
  command->add_option("--smoother", arguments->smoother,
                      "back end: incremental or batch (default: incremental for known..mm-nh, batch for hybrid)")
      ->check(CLI::IsMember({"incremental", "batch"}));
  addSemanticSlamOptions(command, arguments->options.slam);
  command->add_flag("--no-covariances", arguments->noCovariances,
                    "skip the marginal covariance of every pose (no NEES, no ellipses; faster)");
  command->add_flag("--on-known-trajectory", arguments->onKnownTrajectory,
                    "paper B's methods: pin the poses to the known-association estimate (the association ceiling)");
  command->add_option("--pose-error-scale", arguments->poseErrorScale,
                      "with --on-known-trajectory: move each pose k by a draw from N(0, s² Σ_k), Σ_k its known-DA covariance")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--seed", arguments->options.hybrid.seed,
                      "hybrid: seed of the Monte Carlo draws; --pose-error-scale: seed of the pose errors")
      ->check(unsignedInteger64())
      ->capture_default_str();
  addHybridOptions(command, arguments->options.hybrid);
  command->add_flag("--quiet", arguments->quiet, "no progress line");
  command->add_flag("--overwrite", arguments->overwrite, "replace an existing non-empty --out folder whole");
  command->callback([arguments]() { run(*arguments); });
}

}  // namespace semslam::cli
