#include "semslam/run/PoseGraphOptimization.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <variant>

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

bool finiteValues(const Values& values) {
  for (const auto& [key, value] : values) {
    const bool finite = std::visit(
        [](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, Point2> || std::is_same_v<T, Point3>) {
            return v.allFinite();
          } else {
            return v.matrix().allFinite();
          }
        },
        value);
    if (!finite) return false;
  }
  return true;
}

/// A result with a non-finite chi2, gradient or estimate is never reported as a success: the file's numbers
/// (finite, but huge enough that products overflow) caused it.
void requireFiniteResult(const PoseGraphOptimizationReport& report) {
  const OptimizationResult& r = report.result;
  std::string what;
  if (!std::isfinite(report.initialChi2) || !std::isfinite(r.initialChi2)) what = "the initial chi2";
  else if (!std::isfinite(r.initialGradientNorm)) what = "the initial gradient";
  else if (!std::isfinite(report.finalChi2) || !std::isfinite(r.finalChi2)) what = "the final chi2";
  else if (!std::isfinite(r.finalGradientNorm)) what = "the final gradient";
  else if (!finiteValues(report.estimate)) what = "the estimate";
  if (what.empty()) return;
  throw InputError(report.file, 0,
                   what + " is not finite: the file's measurements, information entries or vertices are too large "
                          "(their products overflow a double)");
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
  // chi2 over the file's own edges (the anchoring prior excluded); every edge's is finite (io/PoseGraphBuilder.h),
  // their sum may not be.
  report.initialChi2 = file.factors.chi2(file.initial);
  if (!std::isfinite(report.initialChi2)) {
    throw InputError(options.file, 0,
                     "the chi2 at the initial values is not finite: the file's measurements, information entries "
                     "or vertices are too large (their products overflow a double)");
  }
  try {
    if (options.incremental) {
      replayIncrementally(options, file, marginalKeys, report);
    } else {
      optimizeBatch(options, file, marginalKeys, report);
    }
  } catch (const UnconstrainedSystemError& error) {  // the file's graph leaves something free: its author can fix it
    throw InputError(options.file, 0, std::string(error.what()) + " " + kPoseGraphGaugeHint);
  }
  report.finalChi2 = file.factors.chi2(report.estimate);
  report.fixed = file.fixed;
  report.graph = file.factors;
  requireFiniteResult(report);
  return report;
}

}  // namespace semslam
