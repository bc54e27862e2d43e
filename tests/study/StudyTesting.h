#pragma once
// Helpers of the study tests: a scratch folder, a synthetic log with chosen times, and a small simulated log.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "semslam/io/MeasurementLogFile.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"
#include "semslam/sim/SimulationStreams.h"

namespace semslam::test {

/// A fresh folder for the running test, removed when the object goes.
class StudyScratch {
 public:
  StudyScratch() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("semslam_study_" + std::string(info->test_suite_name()) + "_" +
                                                      info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~StudyScratch() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  StudyScratch(const StudyScratch&) = delete;
  StudyScratch& operator=(const StudyScratch&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// The log's bytes as written by writeMeasurementLog (the strictest equality there is).
inline std::string logBytes(const MeasurementLog& log, const StudyScratch& scratch, const std::string& name) {
  writeMeasurementLog(scratch.file(name), log);
  return fileBytes(scratch.file(name));
}

/// A paper B-style simulated log: 2D loop, `steps` steps, 2 classes, some clutter.
inline MeasurementLog smallSemanticLog(int steps, std::uint64_t seed = 3, int dimension = 2) {
  PathOptions path;
  path.dimension = dimension;
  path.steps = steps;
  path.loops = 1;
  std::mt19937 rng = simulationStream(seed, 0, SimStream::Path);
  const SimTrajectory truth = generatePath(path, rng);
  SemanticSimOptions options;
  options.classes = 2;
  options.landmarkDensity = 0.3;
  options.clutter = 0.2;
  return simulateSemantic(truth, options, seed);
}

}  // namespace semslam::test
