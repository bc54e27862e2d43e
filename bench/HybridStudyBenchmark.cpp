#include "HybridStudyBenchmark.h"

#include <benchmark/benchmark.h>

#include <stdexcept>

#include "semslam/sim/Aliased2dLayout.h"
#include "semslam/study/HybridStudy.h"

namespace semslam::bench {
namespace {

void hybridStudy(benchmark::State& state, const Aliased2dScenario& layout) {
  HybridStudyOptions options;  // the study's defaults: 50 tracks, 10 steps, 6 alphas, sampled, n_s = 1000
  options.layouts = {layout};
  options.threads = 2;
  double runs = 0.0;
  for (auto _ : state) {
    const std::vector<HybridStudyRow> rows = runHybridStudy(options);
    if (failedHybridRuns(rows) > 0) throw std::runtime_error("hybrid study benchmark: a run failed");
    runs += static_cast<double>(rows.size());
  }
  state.counters["runs_per_s"] = benchmark::Counter(runs, benchmark::Counter::kIsRate);
}

}  // namespace

void registerHybridStudyBenchmarks() {
  benchmark::RegisterBenchmark("HybridStudy_fig5_generated_layout_1", hybridStudy, generatedAliased2dScenario(1))
      ->Unit(benchmark::kSecond)
      ->UseRealTime()
      ->Iterations(1);
  benchmark::RegisterBenchmark("HybridStudy_fig5_parking_aisle", hybridStudy, defaultAliased2dScenario())
      ->Unit(benchmark::kSecond)
      ->UseRealTime()
      ->Iterations(1);
}

}  // namespace semslam::bench
