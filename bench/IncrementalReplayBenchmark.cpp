// semslam_incremental_bench: each standard pose graph replayed online, one pose per update (io/PoseGraphReplay.h),
// reading the newest pose's estimate after every update, by
//   - the incremental smoother (solve/IncrementalSmoother.h) with its defaults, then its final convergence
//     (convergeAll), and again with the stricter relinearization of the iSAM2 reference run (0.01, skip 1);
//   - batch re-solving every step (BatchSmoother, Gauss-Newton warm-started from the previous estimate), within a
//     time budget per graph (beyond it the row says how many steps it managed);
//   - and one batch Gauss-Newton solve of the final graph from the file's initial values, interleaved with the
//     incremental replays (up to 5 rounds; medians),
// printed side by side, with the speed ratio  incremental replay (+ final convergence) ÷ one batch GN solve, the
// final chi2 of each and their relative difference, and the cost of fork() of the final smoother.
//
//   semslam_incremental_bench [--budget SECONDS] [--only NAME]    (make bench runs it with the defaults)
//
// The budget (default 120 s) bounds each of the reference-setting replay and the batch re-solving replay.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "Datasets.h"
#include "semslam/io/PoseGraphReplay.h"
#include "semslam/run/PoseGraphReplayLoop.h"
#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/IncrementalSmoother.h"

namespace {

using namespace semslam;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }
double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }  // the batch solve's CPU time

struct ReplayTimes {
  double total = 0.0;  // wall, s: the sum of the step times
  double cpu = 0.0;    // process CPU, s
  double worst = 0.0;
  std::size_t steps = 0;
  bool complete = true;
  double chi2 = 0.0;
  double checkpointGap = 0.0;  // largest relative chi2 excess over a batch solve of the graph so far
};

/// Replays `replay` into `smoother` through the library's replay loop (run/PoseGraphReplayLoop.h). With
/// `checkpoints`, at 1/4, 1/2 and 3/4 of the replay (untimed) compares the estimate with a batch Gauss-Newton solve
/// of the graph so far.
template <class Smoother>
ReplayTimes replayAll(const PoseGraphReplay& replay, Smoother& smoother, double budget, bool checkpoints) {
  ReplayTimes times;
  const std::size_t n = replay.size();
  const auto checkpoint = [&](std::size_t k, const Smoother& s) {
    if (!checkpoints || !(k + 1 == n / 4 || k + 1 == n / 2 || k + 1 == (3 * n) / 4)) return;
    const FactorGraph graph = s.factors();
    const double chi2 = graph.chi2(s.estimate());
    const double optimum = optimize(graph, s.estimate()).finalChi2;
    times.checkpointGap = std::max(times.checkpointGap, (chi2 - optimum) / optimum);
  };
  const ReplayLoopTimes loop = replayPoseGraph(replay, smoother, checkpoint, budget);
  if (loop.checksum < 0) std::printf("?");
  times.total = loop.stepSecondsSum;
  times.cpu = loop.cpuSeconds;
  times.worst = loop.worstStepSeconds;
  times.steps = loop.steps;
  times.complete = loop.complete;
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
  IncrementalSmootherParams reference;  // the setting of the iSAM2 figures
  reference.relinearizeThreshold = 0.01;
  reference.relinearizeSkip = 1;
  const IncrementalSmootherParams defaults;
  std::printf("Online replay, one pose per update, newest pose read after every update; seconds (wall unless -cpu).\n"
              "inc: IncrementalSmoother defaults (relinearize threshold %g, skip %d, wildfire %g); ref: threshold "
              "%g, skip %d.\n",
              defaults.relinearizeThreshold, defaults.relinearizeSkip, defaults.wildfireThreshold,
              reference.relinearizeThreshold, reference.relinearizeSkip);
  std::printf("%-14s %5s %1s| %7s %7s %6s %7s %7s | %7s %7s | %6s %6s | %7s %7s %6s | %9s %8s | %8s %8s %6s\n",
              "dataset", "steps", "n", "inc", "inc-cpu", "final", "worst", "mid-gap", "GN", "GN-cpu", "ratio", "r-cpu",
              "ref", "worst", "ratio", "rebatch", "worst", "chi2-rel", "chi2-ref", "fork");
  for (const bench::Dataset& dataset : bench::datasets()) {
    if (std::find(names.begin(), names.end(), dataset.name) == names.end()) continue;
    if (!only.empty() && dataset.name != only) continue;
    std::string error;
    const bench::PoseGraphProblem* problem = bench::loadProblem(dataset, error);
    if (problem == nullptr) {
      std::printf("%-14s skipped: %s\n", dataset.name.c_str(), error.c_str());
      continue;
    }
    const PoseGraphReplay replay(problem->file);

    // The load of a shared machine drifts within a run, so the batch solve and the incremental replay are
    // interleaved: up to 5 rounds (fewer once the replays have taken 30 s), each one batch Gauss-Newton solve of
    // the final graph and one incremental replay with its final convergence; the medians are reported.
    std::vector<double> wall;
    std::vector<double> cpu;
    std::vector<ReplayTimes> replays;
    std::vector<double> finalWalls;
    std::vector<double> finalCpus;
    std::vector<double> totals;
    double batchChi2 = 0.0;
    double spent = 0.0;
    double forkMs = 0.0;
    for (int round = 0; round < 5 && (round < 1 || spent < 30.0); ++round) {
      const auto start = Clock::now();
      const double cpuStart = cpuSeconds();
      const OptimizationResult batch = optimize(problem->graph, problem->file.initial);
      wall.push_back(since(start));
      cpu.push_back(cpuSeconds() - cpuStart);
      batchChi2 = problem->file.factors.chi2(batch.values);

      IncrementalSmoother incremental(defaults);
      ReplayTimes times = replayAll(replay, incremental, 1e30, round == 0);
      const auto finalStart = Clock::now();
      const double finalCpuStart = cpuSeconds();
      incremental.convergeAll();
      finalWalls.push_back(since(finalStart));
      finalCpus.push_back(cpuSeconds() - finalCpuStart);
      times.chi2 = problem->file.factors.chi2(incremental.estimate());
      if (round > 0) times.checkpointGap = replays.front().checkpointGap;
      replays.push_back(times);
      spent += times.total;
      const auto forkStart = Clock::now();
      const auto fork = incremental.fork();
      forkMs = 1e3 * since(forkStart);
    }
    const auto median = [](std::vector<double> values) {
      std::sort(values.begin(), values.end());
      return values[values.size() / 2];  // the upper median of an even count
    };
    std::vector<double> incWall;
    std::vector<double> incCpu;
    std::vector<double> worst;
    for (std::size_t r = 0; r < replays.size(); ++r) {
      incWall.push_back(replays[r].total);
      incCpu.push_back(replays[r].cpu);
      worst.push_back(replays[r].worst);
    }
    ReplayTimes inc = replays.front();
    inc.total = median(incWall);
    inc.cpu = median(incCpu);
    inc.worst = median(worst);
    const double finalWall = median(finalWalls);
    const double finalCpu = median(finalCpus);
    const double gnWall = median(wall);
    const double gnCpu = median(cpu);
    const std::size_t rounds = replays.size();

    // The reference setting (within the budget), then its final convergence.
    IncrementalSmoother strict(reference);
    ReplayTimes ref = replayAll(replay, strict, budget, false);
    const auto refFinalStart = Clock::now();
    if (ref.complete) strict.convergeAll();
    const double refFinal = since(refFinalStart);
    if (ref.complete) ref.chi2 = problem->file.factors.chi2(strict.estimate());

    // Batch re-solving every step, within the budget.
    BatchSmoother rebatch;
    const ReplayTimes re = replayAll(replay, rebatch, budget, false);

    const auto budgeted = [](const ReplayTimes& t) {
      char text[64];
      if (t.complete) {
        std::snprintf(text, sizeof text, "%.3f", t.total);
      } else {
        std::snprintf(text, sizeof text, ">%.0f@%zu", t.total, t.steps);
      }
      return std::string(text);
    };
    char refRatio[32] = "-";
    char refChi2[32] = "-";
    if (ref.complete) {
      std::snprintf(refRatio, sizeof refRatio, "%.1f", (ref.total + refFinal) / gnWall);
      std::snprintf(refChi2, sizeof refChi2, "%.1e", std::abs(ref.chi2 - batchChi2) / batchChi2);
    }
    std::printf("%-14s %5zu %1zu| %7.3f %7.3f %6.3f %7.4f %7.1e | %7.4f %7.4f | %6.1f %6.1f | %7s %7.4f %6s | "
                "%9s %8.4f | %8.1e %8s %6.2f\n",
                dataset.name.c_str(), replay.size(), rounds, inc.total, inc.cpu, finalWall, inc.worst,
                inc.checkpointGap,
                gnWall, gnCpu, (inc.total + finalWall) / gnWall, (inc.cpu + finalCpu) / gnCpu,
                budgeted(ref).c_str(), ref.worst, refRatio, budgeted(re).c_str(), re.worst,
                std::abs(inc.chi2 - batchChi2) / batchChi2, refChi2, forkMs);
    std::fflush(stdout);
  }
  std::printf(
      "n: interleaved rounds of (batch solve, incremental replay), medians reported; inc: incremental replay (sum of\n"
      "step times), final: its final convergence (convergeAll), worst: its worst step,\n"
      "mid-gap: largest (chi2 - chi2_batch) / chi2_batch at 1/4, 1/2, 3/4 of the replay against a batch Gauss-Newton\n"
      "solve of the graph so far (first round); GN: one batch Gauss-Newton solve of the final graph; ratio:\n"
      "(inc + final) / GN by wall and CPU time; ref: the same replay at the reference setting, its worst step and\n"
      "ratio; rebatch: batch re-solving at every step and its worst step (>T@k: stopped by the budget after k steps);\n"
      "chi2-rel, chi2-ref: |chi2 - chi2_batch| / chi2_batch after the final convergence; fork: ms for fork() of the\n"
      "final smoother.\n");
  return 0;
}
