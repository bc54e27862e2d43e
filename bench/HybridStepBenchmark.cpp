#include "HybridStepBenchmark.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "semslam/hybrid/HybridBelief.h"
#include "semslam/sim/Aliased2dScenario.h"
#include "semslam/sim/Aliased2dSimulator.h"

namespace semslam::bench {
namespace {

constexpr int kSamples = 1000;

/// The log, the problem and the belief just before the first step with detections, for one weight method.
struct SeededBelief {
  MeasurementLog log;
  std::unique_ptr<HybridProblem> problem;
  std::unique_ptr<HybridBelief> belief;
  std::size_t step = 0;

  explicit SeededBelief(WeightMethod method) {
    Aliased2dScenario scenario = defaultAliased2dScenario();
    scenario.alpha = 0.25;
    log = simulateAliased2dTrack(scenario, 1, 0, 10);
    problem = std::make_unique<HybridProblem>(log.header, true);
    HybridOptions options;
    options.weights = method;
    options.samples = kSamples;
    options.seed = 1;
    belief = std::make_unique<HybridBelief>(*problem, options);
    while (step < log.steps.size() && log.steps[step].detections.empty()) belief->update(log.steps[step++]);
    if (step == log.steps.size()) throw std::runtime_error("hybrid step benchmark: the track has no detections");
  }
};

void hybridStep(benchmark::State& state, WeightMethod method) {
  const SeededBelief seeded(method);
  HybridStepReport report;
  double draws = 0.0, weights = 0.0;
  for (auto _ : state) {
    HybridBelief belief = *seeded.belief;
    report = belief.update(seeded.log.steps[seeded.step]);
    benchmark::DoNotOptimize(belief.components().data());
    draws += static_cast<double>(report.weights.sampled) * kSamples;
    weights += static_cast<double>(report.weights.candidates - report.weights.gated);
  }
  state.counters["samples_per_s"] = benchmark::Counter(draws, benchmark::Counter::kIsRate);
  state.counters["weights_per_s"] = benchmark::Counter(weights, benchmark::Counter::kIsRate);
  state.counters["candidates"] = static_cast<double>(report.weights.candidates);
  state.counters["sampled"] = static_cast<double>(report.weights.sampled);
  state.counters["survivors"] = static_cast<double>(report.survivors);
}

}  // namespace

void registerHybridStepBenchmarks() {
  for (WeightMethod method : {WeightMethod::Sampled, WeightMethod::Importance, WeightMethod::Analytic}) {
    benchmark::RegisterBenchmark((std::string("HybridStep_") + weightMethodName(method)).c_str(), hybridStep, method)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

}  // namespace semslam::bench
