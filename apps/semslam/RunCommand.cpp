// semslam run --method M --in LOG --out DIR: one estimation method over one measurement log, scored against its
// truth (run/RunMethod.h: runMethod, writeMethodRun). DIR gets metrics.json (docs/metrics.md) and the run folder
// (src/semslam/io/RunFolder.h; hypotheses.jsonl too for the hybrid methods). A one-line summary goes to standard
// output. With --on-known-trajectory the method runs with its poses pinned to the known-association estimate (and
// --pose-error-scale s: moved inside s times its covariance), what association alone could reach on the log
// (run/KnownTrajectoryCeiling.h).

#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "RunOptions.h"
#include "semslam/core/ProgressBar.h"
#include "semslam/hybrid/HybridRun.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/OutputTarget.h"
#include "semslam/io/StagedFolder.h"
#include "semslam/run/RunMethod.h"

namespace semslam::cli {
namespace {

struct RunArguments {
  std::string in;
  std::string out;
  bool quiet = false;
  bool overwrite = false;
  RunMethodArguments run;  // RunOptions.h: the method and its options, shared with the Python module
};

void printSummary(const RunArguments& arguments, const MeasurementLog& log, const MethodRun& run) {
  const RunMetrics& m = run.evaluation.metrics;
  if (isHybrid(run.method)) {
    std::printf("%s on %s: %zu steps, %lld components at the end, entropy %.4g, err_wmax %.4g m, time %.3f s\n",
                m.method.c_str(), arguments.in.c_str(), log.steps.size(), m.components.value_or(0), m.entropy,
                m.errWmax, m.timeSeconds);
    const std::string bounds = describeBoundsThatBound(run.hybridReports, arguments.run.options.hybrid);
    if (!bounds.empty()) std::fprintf(stderr, "note: %s\n", bounds.c_str());
    return;
  }
  if (run.jointSearchesStopped > 0) {
    std::fprintf(stderr,
                 "note: the joint assignment search stopped at its budget on %d step(s), each keeping the best "
                 "assignment it had found (docs/association-front-end.md §4)\n",
                 run.jointSearchesStopped);
  }
  if (!run.result.historyDecisions.empty()) {
    // Decisions on the true history: the graph's associations are the truth's (DA accuracy 1); the decisions are
    // the figure (docs/association-front-end.md §8b).
    std::printf("%s: decisions right %.4f of true-landmark detections (elsewhere %lld, unassigned %lld, first "
                "sightings forced %lld), clutter rejected at decision %.4f, time %.2f s\n",
                m.method.c_str(), m.decisionAccuracyReal, m.decisionsResightingElsewhere.value_or(0),
                m.decisionsResightingUnassigned.value_or(0), m.decisionsFirstSightingForced.value_or(0),
                m.decisionClutterRejected, run.result.timeSeconds);
  } else {
    std::printf("%s: ATE %.4f m, DA accuracy %.4f, landmarks %lld (true %lld), time %.2f s\n",
                arguments.run.method.c_str(), m.ateRmse, m.daAccuracy, m.landmarksEstimated.value_or(0),
                m.landmarksTrue.value_or(0), run.result.timeSeconds);
  }
}

void run(const RunArguments& arguments) {
  // The folder is checked and staged before the work, and renamed into place whole after it (io/StagedFolder.h).
  requireOutputSparesInput(arguments.out, arguments.in, "--out");
  StagedFolder folder(arguments.out, arguments.overwrite);
  const MeasurementLog log = readMeasurementLog(arguments.in);
  // Every method shows its progress per step (core/ProgressBar.h: in place on a terminal, a line every few
  // seconds elsewhere); --quiet silences it.
  ProgressBar progress("run " + arguments.run.method, static_cast<int>(log.steps.size()), arguments.quiet);
  const MethodRun result =
      runFromArguments(log, arguments.run, arguments.in, [&progress](int done, int) { progress.update(done); });
  writeMethodRun(folder.path(), result);
  folder.commit();
  printSummary(arguments, log, result);
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto arguments = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand("run", "run one estimation method over a measurement log and score it");
  command->add_option("--in", arguments->in, "measurement log (docs/measurement-log.md)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", arguments->out, "output folder")->required();
  addRunMethodOptions(command, arguments->run);
  command->add_flag("--quiet", arguments->quiet, "no progress line");
  command->add_flag("--overwrite", arguments->overwrite, "replace an existing non-empty --out folder whole");
  command->callback([arguments]() { run(*arguments); });
}

}  // namespace semslam::cli
