#include "semslam/run/Demo.h"

#include <filesystem>

#include "semslam/io/MeasurementLogFile.h"
#include "semslam/sim/DemoScenario.h"

namespace semslam {

DemoRun runDemo(const std::string& directory, std::uint64_t seed) {
  namespace fs = std::filesystem;
  DemoRun demo;
  demo.log = simulateDemoLog(seed);
  fs::create_directories(directory);
  demo.logPath = (fs::path(directory) / "demo_log.jsonl").string();
  writeMeasurementLog(demo.logPath, demo.log);

  MethodOptions options;
  options.method = Method::MaxMixtureNullHypothesis;
  demo.maxMixture = runMethod(demo.log, options);
  writeMethodRun(directory, demo.maxMixture);
  options.method = Method::Known;
  demo.known = runMethod(demo.log, options);
  writeMethodRun((fs::path(directory) / "known").string(), demo.known);
  return demo;
}

}  // namespace semslam
