#pragma once
// The readers the fuzz harnesses drive, by harness name (the folder names of fuzz/corpus/ and fuzz/findings/):
// each takes a file path, as every reader of the library does. Shared by the libFuzzer harnesses
// (fuzz/ReaderFuzzer.cpp) and the regression replay in `make test` (tests/io/testCorpusReplay.cpp), so the two
// hold the same readers to the same contract: parse, or throw InputError. The converters' harnesses read a dataset
// folder packed into one file (fuzz/ConverterReaders.h), the options harness a list of option values
// (fuzz/OptionReaders.h).

#include <functional>
#include <map>
#include <string>

#include "ConverterReaders.h"
#include "OptionReaders.h"
#include "semslam/io/EurocFormat.h"
#include "semslam/io/KittiFormat.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/RunMetricsFile.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/io/TumFormat.h"
#include "semslam/models/TabulatedViewpointClassifier.h"

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
      {"classifier", [](const std::string& p) { TabulatedViewpointClassifier::load(p); }},
      {"metrics", [](const std::string& p) { readRunMetrics(p); }},
      {"convert-isam", [](const std::string& p) { convertPacked("isam", p); }},
      {"convert-litw", [](const std::string& p) { convertPacked("utias-lost-in-the-woods", p); }},
      {"convert-starry-night", [](const std::string& p) { convertPacked("utias-starry-night", p); }},
      {"convert-mrclam", [](const std::string& p) { convertPacked("mrclam", p); }},
      {"convert-kitti-tracking", [](const std::string& p) { convertPacked("kitti-tracking", p); }},
      {"options", [](const std::string& p) { parseNumericOptions(p); }},
  };
  return table;
}

}  // namespace semslam::fuzz
