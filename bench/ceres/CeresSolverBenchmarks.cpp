#include "CeresSolverBenchmarks.h"

#include <benchmark/benchmark.h>

#include <exception>
#include <optional>
#include <string>

#include "AutodiffPoseGraph2.h"
#include "CeresPoseGraph.h"
#include "Datasets.h"
#include "RatioTable.h"

namespace semslam::bench {

namespace {

template <class CeresProblem>
void solveWithCeres(benchmark::State& state, const Dataset& dataset, int threads) {
  std::string error;
  const PoseGraphProblem* problem = loadProblem(dataset, error);
  if (problem == nullptr) {
    state.SkipWithError(error.c_str());
    return;
  }
  const ceres::Solver::Options options = ceresOptions(threads);
  // The last problem outlives the loop, for the counters; each earlier one is destroyed inside the timed region,
  // as each earlier result of ours is.
  std::optional<CeresProblem> ceresProblem;
  ceres::Solver::Summary summary;
  try {
    for (auto _ : state) {
      ceresProblem.emplace(problem->graph, problem->file.initial);
      summary = ceresProblem->solve(options);
      benchmark::DoNotOptimize(summary.final_cost);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  if (!summary.IsSolutionUsable()) {
    state.SkipWithError(("Ceres failed: " + summary.message).c_str());
    return;
  }
  state.counters[kChi2Counter] = problem->file.factors.chi2(ceresProblem->values());
  state.counters[kIterationsCounter] = summary.num_successful_steps + summary.num_unsuccessful_steps;
  state.counters["converged"] = summary.termination_type == ceres::CONVERGENCE ? 1.0 : 0.0;
}

}  // namespace

void registerCeresSolverBenchmarks(const Dataset& dataset) {
  for (const auto& [name, threads] : {std::pair{kCeres1Thread, 1}, std::pair{kCeres2Threads, 2}}) {
    benchmark::RegisterBenchmark((std::string(name) + "/" + dataset.name).c_str(), solveWithCeres<CeresPoseGraph>,
                                 dataset, threads)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MeasureProcessCPUTime();
  }
  if (dataset.planarPosesOnly) {
    benchmark::RegisterBenchmark((std::string(kCeresAutodiff) + "/" + dataset.name).c_str(),
                                 solveWithCeres<AutodiffPoseGraph2>, dataset, 1)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MeasureProcessCPUTime();
  }
}

}  // namespace semslam::bench
