#pragma once
// PoseGraphReplayLoop: the online replay of a pose graph (io/PoseGraphReplay.h) through a smoother, one pose per
// update, reading the newest pose's estimate after every update as an online front end would, and timing every
// step. The one replay loop of `semslam optimize --incremental` (run/PoseGraphOptimization.h) and of the
// incremental benchmark (bench/IncrementalReplayBenchmark.cpp); templated on the smoother so that the benchmark can
// replay the batch smoother (BatchSmoother) through the same loop.
//
// A step's time is that of step(k) + update + the newest-pose read (wall and process CPU); afterStep(k, smoother)
// runs after the step's clock has stopped (statistics, untimed checkpoints). With a budget, the loop stops once
// the steps' summed wall time exceeds it (complete = false, `steps` says how many were done).

#include <algorithm>
#include <chrono>
#include <ctime>
#include <limits>
#include <vector>

#include "semslam/io/PoseGraphReplay.h"

namespace semslam {

struct ReplayLoopTimes {
  std::vector<double> stepSeconds;  ///< wall time of every step done
  double stepSecondsSum = 0.0;      ///< their sum
  double cpuSeconds = 0.0;          ///< process CPU time of the steps
  double elapsedSeconds = 0.0;      ///< wall time of the whole loop, afterStep included
  double worstStepSeconds = 0.0;
  std::size_t worstStep = 0;
  std::size_t steps = 0;
  bool complete = true;             ///< every step was done (not stopped by the budget)
  double checksum = 0.0;            ///< sum of the newest poses' dimensions: keeps the reads observable
};

template <class Smoother, class AfterStep>
ReplayLoopTimes replayPoseGraph(const PoseGraphReplay& replay, Smoother& smoother, AfterStep&& afterStep,
                                double budgetSeconds = std::numeric_limits<double>::infinity()) {
  using Clock = std::chrono::steady_clock;
  const auto cpuNow = [] { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; };
  ReplayLoopTimes times;
  times.stepSeconds.reserve(replay.size());
  const auto start = Clock::now();
  for (std::size_t k = 0; k < replay.size(); ++k) {
    const auto stepStart = Clock::now();
    const double cpuStart = cpuNow();
    const ReplayStep step = replay.step(k, smoother.estimate());
    smoother.update(step.factors, step.values);
    times.checksum += dimension(smoother.estimate().value(step.pose));  // the newest pose, as a front end reads it
    const double seconds = std::chrono::duration<double>(Clock::now() - stepStart).count();
    times.cpuSeconds += cpuNow() - cpuStart;
    times.stepSeconds.push_back(seconds);
    times.stepSecondsSum += seconds;
    if (seconds > times.worstStepSeconds || times.steps == 0) {
      times.worstStepSeconds = seconds;
      times.worstStep = k;
    }
    ++times.steps;
    afterStep(k, smoother);
    if (times.stepSecondsSum > budgetSeconds && k + 1 < replay.size()) {
      times.complete = false;
      break;
    }
  }
  times.elapsedSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  return times;
}

}  // namespace semslam
