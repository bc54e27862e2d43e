// semslam_incremental_bench: each standard pose graph replayed online, one pose per update (io/PoseGraphReplay.h),
// reading the newest pose's estimate after every update, by
//   - the incremental smoother (solve/IncrementalSmoother.h), then its final convergence (convergeAll);
//   - batch re-solving every step (BatchSmoother, Gauss-Newton warm-started from the previous estimate), within a
//     time budget per graph (beyond it the row says how many steps it managed);
//   - and one batch Gauss-Newton solve of the final graph from the file's initial values (median of 3),
// printed side by side, with the speed ratio  incremental replay (+ final convergence) ÷ one batch GN solve, the
// final chi2 of each and their relative difference, and the cost of fork() of the final smoother.
//
//   semslam_incremental_bench [--budget SECONDS] [--only NAME]    (make bench runs it with the defaults)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "Datasets.h"
#include "semslam/io/PoseGraphReplay.h"
#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/IncrementalSmoother.h"

namespace {

using namespace semslam;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }
double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct ReplayTimes {
  double total = 0.0;  // wall, s
  double cpu = 0.0;    // process CPU, s
  double worst = 0.0;
  std::size_t steps = 0;
  bool complete = true;
  double chi2 = 0.0;
};

template <class Smoother>
ReplayTimes replayAll(const PoseGraphReplay& replay, Smoother& smoother, double budget) {
  ReplayTimes times;
  double checksum = 0.0;
  const auto start = Clock::now();
  const double cpuStart = cpuSeconds();
  for (std::size_t k = 0; k < replay.size(); ++k) {
    const auto stepStart = Clock::now();
    const ReplayStep step = replay.step(k, smoother.estimate());
    smoother.update(step.factors, step.values);
    checksum += dimension(smoother.estimate().value(step.pose));  // the newest pose, as a front end reads it
    times.worst = std::max(times.worst, since(stepStart));
    ++times.steps;
    if (since(start) > budget && k + 1 < replay.size()) {
      times.complete = false;
      break;
    }
  }
  times.total = since(start);
  times.cpu = cpuSeconds() - cpuStart;
  if (checksum < 0) std::printf("?");
  return times;
}

}  // namespace

int main(int argc, char** argv) {
  double budget = 120.0;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--budget") == 0 && i + 1 < argc) {
      budget = std::stod(argv[++i]);
    } else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--budget SECONDS] [--only DATASET]\n", argv[0]);
      return 2;
    }
  }
  const std::vector<std::string> names = {"manhattan", "intel", "ring", "sphere2500", "cityTrees10000"};
  std::printf("Online replay, one pose per update, newest pose read after every update. Wall seconds (CPU).\n");
  std::printf("%-15s %6s | %9s %9s %9s %9s | %9s %9s | %8s %8s | %8s %8s | %9s %8s\n", "dataset", "steps",
              "inc", "inc-cpu", "+final", "worst", "batch-GN", "GN-cpu", "ratio", "ratio-cpu", "rebatch", "worst",
              "chi2-rel", "fork-ms");
  for (const bench::Dataset& dataset : bench::datasets()) {
    if (std::find(names.begin(), names.end(), dataset.name) == names.end()) continue;
    if (!only.empty() && dataset.name != only) continue;
    std::string error;
    const bench::PoseGraphProblem* problem = bench::loadProblem(dataset, error);
    if (problem == nullptr) {
      std::printf("%-15s skipped: %s\n", dataset.name.c_str(), error.c_str());
      continue;
    }
    const PoseGraphReplay replay(problem->file);

    // One batch Gauss-Newton solve of the final graph (median of 3).
    std::vector<double> wall;
    std::vector<double> cpu;
    OptimizationResult batch;
    for (int r = 0; r < 3; ++r) {
      const auto start = Clock::now();
      const double cpuStart = cpuSeconds();
      batch = optimize(problem->graph, problem->file.initial);
      wall.push_back(since(start));
      cpu.push_back(cpuSeconds() - cpuStart);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    const double batchChi2 = problem->file.factors.chi2(batch.values);

    // The incremental replay, then its final convergence.
    IncrementalSmoother incremental;
    ReplayTimes inc = replayAll(replay, incremental, 1e30);
    const auto finalStart = Clock::now();
    const double finalCpuStart = cpuSeconds();
    incremental.convergeAll();
    const double finalWall = since(finalStart);
    const double finalCpu = cpuSeconds() - finalCpuStart;
    inc.chi2 = problem->file.factors.chi2(incremental.estimate());
    const auto forkStart = Clock::now();
    const auto fork = incremental.fork();
    const double forkMs = 1e3 * since(forkStart);

    // Batch re-solving every step, within the budget.
    BatchSmoother rebatch;
    const ReplayTimes re = replayAll(replay, rebatch, budget);

    char rebatchText[64];
    if (re.complete) {
      std::snprintf(rebatchText, sizeof rebatchText, "%8.2f", re.total);
    } else {
      std::snprintf(rebatchText, sizeof rebatchText, ">%.0f@%zu", re.total, re.steps);
    }
    std::printf("%-15s %6zu | %9.3f %9.3f %9.3f %9.4f | %9.4f %9.4f | %8.1f %8.1f | %8s %8.4f | %9.1e %8.2f\n",
                dataset.name.c_str(), replay.size(), inc.total, inc.cpu, finalWall, inc.worst, wall[1], cpu[1],
                (inc.total + finalWall) / wall[1], (inc.cpu + finalCpu) / cpu[1], rebatchText, re.worst,
                std::abs(inc.chi2 - batchChi2) / batchChi2, forkMs);
    std::fflush(stdout);
  }
  std::printf(
      "inc: incremental replay (wall), inc-cpu its CPU time, +final: its final convergence (convergeAll), worst: its\n"
      "worst step; batch-GN: one Gauss-Newton solve of the final graph (median of 3); ratio: (inc + final) / batch-GN,\n"
      "by wall and CPU time; rebatch: batch re-solving at every step (>T@k: stopped by the budget after k steps) and\n"
      "its worst step; chi2-rel: |chi2_inc - chi2_batch| / chi2_batch after the final convergence; fork-ms: fork()\n"
      "of the final smoother.\n");
  return 0;
}
