#include "RealLogRunBenchmark.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include "Datasets.h"
#include "semslam/io/convert/DatasetConverters.h"
#include "semslam/run/RunMethod.h"

namespace semslam::bench {
namespace {

struct Recording {
  const char* benchmarkName;
  const char* kind;          // the converter, as `semslam convert KIND` names it
  const char* relativePath;  // below the data directory
};

void realLogRun(benchmark::State& state, Recording recording) {
  const std::string path = dataDirectory() + "/" + recording.relativePath;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path + " is absent").c_str());
    return;
  }
  ConvertOptions convert;
  convert.classes = 3;
  convert.misclassification = 0.1;
  convert.keyframePeriod = 1.0;
  convert.robot = 1;
  MeasurementLog log;
  try {
    log = convertDataset(recording.kind, path, convert);
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
    return;
  }
  const double duration = log.steps.empty() ? 0.0 : log.steps.back().time - log.steps.front().time;
  MethodOptions options;
  options.method = Method::MaxMixtureNullHypothesis;
  options.poseCovariances = false;
  options.runFolder = false;
  std::optional<MethodRun> run;
  double wallSeconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    run = runMethod(log, options);
    wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(run->result.poses.data());
  }
  state.counters["real_time_factor"] = duration / (wallSeconds / static_cast<double>(state.iterations()));
  state.counters["da_accuracy_real"] = run->evaluation.metrics.daAccuracyReal;
}

}  // namespace

void registerRealLogRunBenchmarks() {
  for (const Recording& recording : {Recording{"RealLogRun_litw", "utias-lost-in-the-woods", "utias-lost-in-the-woods"},
                                     Recording{"RealLogRun_mrclam_robot1", "mrclam", "mrclam/MRCLAM_Dataset6"}}) {
    benchmark::RegisterBenchmark(recording.benchmarkName, realLogRun, recording)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  }
}

}  // namespace semslam::bench
