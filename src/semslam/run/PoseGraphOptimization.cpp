#include "semslam/run/PoseGraphOptimization.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "semslam/core/InputError.h"
#include "semslam/io/PoseGraphAnchor.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/PoseGraphReplay.h"
#include "semslam/run/PoseGraphReplayLoop.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<Key> parseKeyList(const std::string& list, const Values& values) {
  std::vector<Key> keys;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    Key key = 0;
    try {
      key = keyFromString(item);
    } catch (const std::invalid_argument& error) {
      throw InputError("--marginals: " + std::string(error.what()));
    }
    if (!values.exists(key)) throw InputError("--marginals: the graph has no variable " + item);
    keys.push_back(key);
  }
  if (keys.empty()) throw InputError("--marginals: no ids given");
  return keys;
}

void optimizeBatch(const PoseGraphOptimizationOptions& options, const PoseGraphFile& file,
                   const std::vector<Key>& marginalKeys, PoseGraphOptimizationReport& report) {
  FactorGraph graph = file.factors;
  graph.add(anchorFactors(file));
  OptimizerParams params;
  params.solver = options.solver;
  params.maxIterations = options.maxIterations;
  params.verbose = options.verbose;
  const auto start = std::chrono::steady_clock::now();
  report.result = optimize(graph, file.initial, params);
  report.seconds = secondsSince(start);
  report.estimate = report.result.values;
  if (!marginalKeys.empty()) report.marginals = Marginals(graph, report.estimate).jointMarginal(marginalKeys);
}

void replayIncrementally(const PoseGraphOptimizationOptions& options, const PoseGraphFile& file,
                         const std::vector<Key>& marginalKeys, PoseGraphOptimizationReport& report) {
  const PoseGraphReplay replay(file);
  IncrementalSmoother smoother(options.incrementalParams);
  PoseGraphReplayStatistics statistics;
  double reeliminated = 0.0, relinearized = 0.0, solved = 0.0;
  const ReplayLoopTimes times = replayPoseGraph(replay, smoother, [&](std::size_t k, const IncrementalSmoother& s) {
    reeliminated += s.lastUpdate().reeliminatedVariables;
    relinearized += s.lastUpdate().relinearizedVariables;
    solved += s.lastUpdate().solvedCliques;
    statistics.fullReorderings += s.lastUpdate().fullReordering ? 1 : 0;
    if (options.progress) options.progress(static_cast<int>(k + 1), static_cast<int>(replay.size()));
  });
  if (options.finalConvergence) {
    OptimizerParams params;
    params.maxIterations = options.maxIterations;
    const auto start = std::chrono::steady_clock::now();
    report.result = smoother.convergeAll(params);
    statistics.finalConvergenceSeconds = secondsSince(start);
  }
  const double steps = std::max<double>(1.0, static_cast<double>(replay.size()));
  statistics.steps = replay.size();
  statistics.stepSeconds = times.stepSeconds;
  statistics.replaySeconds = times.elapsedSeconds;
  statistics.worstStepSeconds = times.worstStepSeconds;
  statistics.worstStep = times.worstStep;
  statistics.checksum = times.checksum;
  statistics.finalConvergence = options.finalConvergence;
  statistics.params = options.incrementalParams;
  statistics.meanReeliminatedVariables = reeliminated / steps;
  statistics.meanRelinearizedVariables = relinearized / steps;
  statistics.meanSolvedCliques = solved / steps;
  statistics.cliques = smoother.cliqueCount();
  statistics.factorEntries = smoother.factorEntries();
  report.seconds = statistics.replaySeconds + statistics.finalConvergenceSeconds;
  report.estimate = smoother.estimate();
  if (!marginalKeys.empty()) report.marginals = smoother.jointMarginal(marginalKeys);
  report.replay = std::move(statistics);
}

}  // namespace

const char* const kPoseGraphGaugeHint =
    "(A pose-graph file is held in place by its first vertex, or by the vertices of its FIX lines: every other "
    "vertex needs a chain of edges to one of them; a separate part needs a FIX line of its own.)";

PoseGraphOptimizationReport optimizePoseGraphFile(const PoseGraphOptimizationOptions& options) {
  const PoseGraphFile file = readPoseGraph(options.file, parseGraphFormat(options.format));
  std::vector<Key> marginalKeys;
  if (!options.marginals.empty()) marginalKeys = parseKeyList(options.marginals, file.initial);
  PoseGraphOptimizationReport report;
  report.file = options.file;
  report.format = options.format;
  report.solver = options.incremental                                  ? "incremental"
                  : options.solver == SolverType::LevenbergMarquardt ? "lm"
                                                                       : "gn";
  report.variables = file.initial.size();
  report.edges = file.factors.size();
  try {
    if (options.incremental) {
      replayIncrementally(options, file, marginalKeys, report);
    } else {
      optimizeBatch(options, file, marginalKeys, report);
    }
  } catch (const UnconstrainedSystemError& error) {  // the file's graph leaves something free: its author can fix it
    throw InputError(options.file, 0, std::string(error.what()) + " " + kPoseGraphGaugeHint);
  }
  // chi2 over the file's own edges (the anchoring prior excluded).
  report.initialChi2 = file.factors.chi2(file.initial);
  report.finalChi2 = file.factors.chi2(report.estimate);
  report.fixed = file.fixed;
  report.graph = file.factors;
  return report;
}

}  // namespace semslam
