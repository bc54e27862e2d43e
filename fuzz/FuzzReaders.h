#pragma once
// The readers the fuzz harnesses drive, by harness name (the folder names of fuzz/corpus/ and fuzz/findings/):
// each takes a file path, as every reader of the library does. Shared by the libFuzzer harnesses
// (fuzz/ReaderFuzzer.cpp) and the regression replay in `make test` (tests/io/testCorpusReplay.cpp), so the two
// hold the same readers to the same contract: parse, or throw InputError.

#include <functional>
#include <map>
#include <string>

#include "semslam/io/EurocFormat.h"
#include "semslam/io/KittiFormat.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/io/TumFormat.h"

namespace semslam::fuzz {

using Reader = std::function<void(const std::string& path)>;

inline const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> table = {
      {"g2o", [](const std::string& p) { readPoseGraph(p, GraphFormat::G2o); }},
      {"toro", [](const std::string& p) { readPoseGraph(p, GraphFormat::Toro); }},
      {"isam", [](const std::string& p) { readPoseGraph(p, GraphFormat::Isam); }},
      {"log", [](const std::string& p) { readMeasurementLog(p); }},
      {"tum", [](const std::string& p) { readTumTrajectory(p); }},
      {"kitti", [](const std::string& p) { readKittiTrajectory(p); }},
      {"euroc", [](const std::string& p) { readEurocTrajectory(p); }},
      {"scenario", [](const std::string& p) { readAliased2dScenario(p); }},
  };
  return table;
}

}  // namespace semslam::fuzz
