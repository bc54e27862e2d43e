#include "SemslamSolverBenchmarks.h"

#include <benchmark/benchmark.h>

#include <exception>
#include <string>

#include "Datasets.h"
#include "RatioTable.h"
#include "semslam/solve/Optimizer.h"

namespace semslam::bench {

namespace {

void solveWithSemslam(benchmark::State& state, const Dataset& dataset, SolverType solver) {
  std::string error;
  const PoseGraphProblem* problem = loadProblem(dataset, error);
  if (problem == nullptr) {
    state.SkipWithError(error.c_str());
    return;
  }
  OptimizerParams params;
  params.solver = solver;
  OptimizationResult result;
  try {
    for (auto _ : state) {
      result = optimize(problem->graph, problem->file.initial, params);
      benchmark::DoNotOptimize(result.finalChi2);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters[kChi2Counter] = problem->file.factors.chi2(result.values);
  state.counters[kIterationsCounter] = result.iterations;
  state.counters["converged"] = result.converged ? 1.0 : 0.0;
}

}  // namespace

void registerSemslamSolverBenchmarks(const Dataset& dataset) {
  for (const auto& [name, solver] : {std::pair{kOursGaussNewton, SolverType::GaussNewton},
                                     std::pair{kOursLevenbergMarquardt, SolverType::LevenbergMarquardt}}) {
    benchmark::RegisterBenchmark((std::string(name) + "/" + dataset.name).c_str(), solveWithSemslam, dataset, solver)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MeasureProcessCPUTime();
  }
}

}  // namespace semslam::bench
