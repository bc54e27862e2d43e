// semslam_bench: our solvers and Ceres on the standard pose graphs, then the ratio table (RatioTable.h); one step
// of the hybrid belief with each weight method (HybridStepBenchmark.h); paper A's whole study on one layout
// (HybridStudyBenchmark.h); a mixture-heavy mm-nh run on each back end (MixtureRunBenchmark.h); mm-nh on whole real
// recordings against real time (RealLogRunBenchmark.h).
//
//   semslam_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true   (what `make bench` runs)
//   semslam_bench --benchmark_filter=manhattan                                       (one dataset)
//   semslam_bench --benchmark_filter=HybridStep                                      (the hybrid step)
//   semslam_bench --benchmark_filter=HybridStudy                                     (paper A's study)
//   semslam_bench --benchmark_filter=MixtureRun                                      (mm-nh on both back ends)
//   semslam_bench --benchmark_filter=RealLogRun                                      (mm-nh on real recordings)

#include <benchmark/benchmark.h>

#include <cstdio>

#include "Datasets.h"
#include "HybridStepBenchmark.h"
#include "HybridStudyBenchmark.h"
#include "MixtureRunBenchmark.h"
#include "RealLogRunBenchmark.h"
#include "RatioTable.h"
#include "SemslamSolverBenchmarks.h"
#ifdef SEMSLAM_BENCH_HAVE_CERES
#include "ceres/CeresSolverBenchmarks.h"
#endif

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  for (const semslam::bench::Dataset& dataset : semslam::bench::datasets()) {
    semslam::bench::registerSemslamSolverBenchmarks(dataset);
#ifdef SEMSLAM_BENCH_HAVE_CERES
    semslam::bench::registerCeresSolverBenchmarks(dataset);
#endif
  }
  semslam::bench::registerHybridStepBenchmarks();
  semslam::bench::registerHybridStudyBenchmarks();
  semslam::bench::registerMixtureRunBenchmarks();
  semslam::bench::registerRealLogRunBenchmarks();
#ifndef SEMSLAM_BENCH_HAVE_CERES
  std::printf("semslam_bench was built without Ceres (find_package(Ceres) failed): our solvers only\n");
#endif

  semslam::bench::RatioTable table;
  semslam::bench::RatioTableReporter reporter(table);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  table.print(stdout);
  benchmark::Shutdown();
  return 0;
}
