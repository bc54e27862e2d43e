#include "semslam/run/RunMethod.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "semslam/core/Version.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/HypothesesJsonl.h"
#include "semslam/io/RunMetricsFile.h"
#include "semslam/io/RunOutputFromResult.h"
#include "semslam/run/MethodSettings.h"
#include "semslam/slam/LoopClosureBranches.h"
#include "semslam/slam/SemanticSlamSmoother.h"

namespace semslam {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Paper B: the pipeline over every step, the final estimate, and each detection's chosen landmark.
void runSemanticSlam(const MeasurementLog& log, const MethodOptions& options, const RunProgress& progress,
                     MethodRun& run) {
  SemanticSlamOptions slamOptions = options.slam;
  slamOptions.strategy = associationStrategy(options.method);
  if (options.smoother || options.switchRounds > 0 || options.relinearizeThreshold || options.relinearizeSkip) {
    IncrementalSmootherParams incremental = semanticSlamSmootherParams();
    incremental.maxSwitchRounds = options.switchRounds;
    incremental.relinearizeThreshold = options.relinearizeThreshold.value_or(incremental.relinearizeThreshold);
    incremental.relinearizeSkip = options.relinearizeSkip.value_or(incremental.relinearizeSkip);
    slamOptions.smoother = smootherFactory(options.smoother.value_or(SmootherKind::Incremental), {}, incremental);
  }

  const auto start = std::chrono::steady_clock::now();
  LoopClosureBranches branches(log.header, slamOptions);  // one branch throughout unless a window is set
  const int steps = static_cast<int>(log.steps.size());
  for (int k = 0; k < steps; ++k) {
    branches.addStep(log.steps[k]);
    if (progress) progress(k + 1, steps);
  }
  branches.finish();
  const SemanticSlam& slam = branches.slam();
  run.result = slam.result(options.poseCovariances);
  run.result.timeSeconds = secondsSince(start);
  run.factors = slam.smoother().factors().size();
  run.jointSearchesStopped = slam.jointSearchesStopped();
  if (options.keepFinalGraph) {
    run.finalGraph = slam.smoother().factors();
    run.finalEstimate = slam.smoother().estimate();
  }
  run.evaluation = evaluateRun(log, run.result);
  if (!options.runFolder) return;
  std::vector<AssociationRecord> associations;
  for (const DetectionRecord& record : slam.detections()) {
    const auto [landmark, weight] = slam.chosenAssociation(record);
    if (slam.graphFollowsTruth() && !landmark) continue;  // clutter: no factor
    associations.push_back({record.step, record.detection, landmark, weight, record.truth, slam.residualChi2(record)});
  }
  run.output = runOutputFrom(log, run.result, std::move(associations));
  for (const LoopClosureBranches::Split& split : branches.splits()) {
    run.output.branchSplits.push_back({split.openedAt, split.closedAfter, split.scoreA, split.scoreB, split.scoreC,
                                       LoopClosureBranches::branchName(split.kept)});
  }
  for (std::size_t k = 0; k < run.result.historyDecisions.size(); ++k) {
    const std::vector<HistoryDecision>& decisions = run.result.historyDecisions[k];
    for (std::size_t i = 0; i < decisions.size(); ++i) {
      run.output.decisions.push_back(
          {static_cast<int>(k), static_cast<int>(i), decisions[i], log.steps[k].detections[i].truthId});
    }
  }
}

/// Paper A: every detection of the heaviest final component's history, weighted by that history's association
/// marginal P(β_1:k | H_k) (A, eq. 8).
std::vector<AssociationRecord> hybridAssociationRecords(const MeasurementLog& log, const HybridRunOutput& hybrid) {
  const RunResult& result = hybrid.result;
  double historyWeight = 1.0;
  if (!hybrid.reports.empty() && !result.components.empty()) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < result.components.size(); ++i) {
      if (result.components[i].weight > result.components[best].weight) best = i;
    }
    for (const AssociationHypothesis& a : hybrid.finalMarginals.association) {
      if (a.associations == result.components[best].associations) historyWeight = a.weight;
    }
  }
  std::vector<AssociationRecord> records;
  for (std::size_t k = 0; k < result.associations.size(); ++k) {
    for (std::size_t i = 0; i < result.associations[k].size(); ++i) {
      records.push_back({static_cast<int>(k), static_cast<int>(i), result.associations[k][i], historyWeight,
                         log.steps[k].detections[i].truthId, std::nullopt});  // the hybrid belief reports no chi2
    }
  }
  return records;
}

/// Paper A: the hybrid belief over every step; the final estimate is its heaviest component (HybridRun.h).
void runHybridBelief(const MeasurementLog& log, const MethodOptions& options, const RunProgress& progress,
                     MethodRun& run) {
  HybridOptions hybridOptions = options.hybrid;
  hybridOptions.useSemantics = options.method == Method::Hybrid;
  if (options.smoother == SmootherKind::Incremental) {
    hybridOptions.smootherFactory = smootherFactory(SmootherKind::Incremental);
  }
  if (options.runFolder) run.hypothesesJsonl.emplace();
  const HybridStepObserver observe = [&](const HybridStepRecord& record) {
    const int k = record.marginals.step;
    run.hybridStepMetrics.push_back(evaluateHypotheses(record.marginals.components, log.steps[k].truePose));
    if (run.hypothesesJsonl) {
      run.hypothesesJsonl->append(hypothesesJsonLine(record, run.hybridStepMetrics.back()) + "\n");
    }
  };
  HybridRunOutput hybrid = runHybrid(log, hybridOptions, progress, observe);
  run.evaluation = evaluateRun(log, hybrid.result);
  if (options.runFolder) run.output = runOutputFrom(log, hybrid.result, hybridAssociationRecords(log, hybrid));
  run.result = std::move(hybrid.result);
  run.hybridReports = std::move(hybrid.reports);
  run.hybridFinal = std::move(hybrid.finalMarginals);
}

}  // namespace

MethodRun runMethod(const MeasurementLog& log, const MethodOptions& options, const RunProgress& progress) {
  if (options.switchRounds < 0) throw std::invalid_argument("switch rounds must be >= 0");
  if (options.switchRounds > 0) {
    if (options.method != Method::MaxMixture && options.method != Method::MaxMixtureNullHypothesis) {
      throw std::invalid_argument("switch rounds apply to mm and mm-nh: " + methodName(options.method) +
                                  " has no max-mixture to switch");
    }
    if (options.smoother == SmootherKind::Batch) {
      throw std::invalid_argument("switch rounds apply to the incremental back end: the batch back end re-chooses "
                                  "every mixture at every Gauss-Newton iterate");
    }
  }
  if (options.relinearizeThreshold || options.relinearizeSkip) {
    if (isHybrid(options.method)) {
      throw std::invalid_argument("the relinearization options apply to paper B's incremental back end: " +
                                  methodName(options.method) + " has its own");
    }
    if (options.smoother == SmootherKind::Batch) {
      throw std::invalid_argument("the relinearization options apply to the incremental back end: the batch back "
                                  "end relinearizes everything at every Gauss-Newton iterate");
    }
    if (options.relinearizeThreshold && !(*options.relinearizeThreshold >= 0.0 &&
                                          std::isfinite(*options.relinearizeThreshold))) {
      throw std::invalid_argument("the relinearization threshold must be finite and >= 0");
    }
    if (options.relinearizeSkip && *options.relinearizeSkip < 1) {
      throw std::invalid_argument("the relinearization skip must be >= 1 (1: check at every update)");
    }
  }
  if (options.slam.decideOnTrueHistory && isHybrid(options.method)) {  // (known: SemanticSlam refuses it)
    throw std::invalid_argument("decisions on the true history are paper B's front end's: " +
                                methodName(options.method) + " takes none");
  }
  if (options.slam.nullEscapeWindow != 0.0 && !options.slam.nullEscape) {  // (mm-nh's, like its other options)
    throw std::invalid_argument("the null escape window widens the null escape, which --no-null-escape turns off");
  }
  MethodRun run;
  run.method = options.method;
  run.hasRunFolder = options.runFolder;
  if (isHybrid(options.method)) {
    runHybridBelief(log, options, progress, run);
  } else {
    runSemanticSlam(log, options, progress, run);
  }
  run.settings = methodSettings(options);
  return run;
}

void writeMethodRun(const std::string& directory, const MethodRun& run) {
  if (!run.hasRunFolder) throw std::invalid_argument("writeMethodRun: the run was made without options.runFolder");
  std::filesystem::create_directories(directory);
  const std::filesystem::path dir(directory);
  writeRunFolder(directory, run.output);
  writeRunMetrics((dir / "metrics.json").string(), run.evaluation.metrics);
  nlohmann::json settings = {{"schema", "semslam.settings/1"}, {"version", std::string(version())}};
  settings.update(run.settings);
  writeFileAtomically((dir / "settings.json").string(),
                      [&settings](std::ostream& out) { out << settings.dump(2) << '\n'; });
  if (isHybrid(run.method)) {
    writeHypothesesJsonl((dir / "hypotheses.jsonl").string(), *run.hypothesesJsonl);
  }
}

}  // namespace semslam
