#include "MixtureRunBenchmark.h"

#include <benchmark/benchmark.h>

#include <random>
#include <utility>

#include "semslam/run/RunMethod.h"
#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"

namespace semslam::bench {
namespace {

MeasurementLog mixtureHeavyLog() {
  PathOptions path;
  path.steps = 300;
  path.loops = 2;
  std::mt19937 rng(1);
  SemanticSimOptions options;
  options.classes = 3;
  options.landmarkDensity = 0.3;
  options.misclassification = 0.1;
  options.clutter = 0.2;
  return simulateSemantic(generatePath(path, rng), options, 1);
}

/// The back ends compared: the incremental smoother with paper B's defaults, with component re-choice on
/// (maxSwitchRounds 5), and the batch smoother.
enum class BackEnd { Incremental, IncrementalSwitching, Batch };

void mixtureRun(benchmark::State& state, BackEnd backEnd) {
  const MeasurementLog log = mixtureHeavyLog();
  MethodOptions options;
  options.method = Method::MaxMixtureNullHypothesis;
  options.smoother = backEnd == BackEnd::Batch ? SmootherKind::Batch : SmootherKind::Incremental;
  if (backEnd == BackEnd::IncrementalSwitching) options.switchRounds = 5;
  options.poseCovariances = false;
  options.runFolder = false;
  MethodRun run;
  for (auto _ : state) {
    run = runMethod(log, options);
    benchmark::DoNotOptimize(run.result.poses.data());
  }
  state.counters["ate_rmse"] = run.evaluation.metrics.ateRmse;
  state.counters["da_accuracy"] = run.evaluation.metrics.daAccuracy;
}

}  // namespace

void registerMixtureRunBenchmarks() {
  const std::pair<const char*, BackEnd> backEnds[] = {
      {"MixtureRun_incremental", BackEnd::Incremental},
      {"MixtureRun_incremental_switching", BackEnd::IncrementalSwitching},
      {"MixtureRun_batch", BackEnd::Batch}};
  for (const auto& [name, backEnd] : backEnds) {
    benchmark::RegisterBenchmark(name, mixtureRun, backEnd)->Unit(benchmark::kMillisecond)->UseRealTime();
  }
}

}  // namespace semslam::bench
