#include "semslam/run/Demo.h"

#include <filesystem>

#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/StagedFolder.h"
#include "semslam/sim/DemoScenario.h"

namespace semslam {

DemoRun runDemo(const std::string& directory, std::uint64_t seed, bool overwrite) {
  namespace fs = std::filesystem;
  StagedFolder folder(directory, overwrite);
  DemoRun demo;
  demo.log = simulateDemoLog(seed);
  writeMeasurementLog((fs::path(folder.path()) / "demo_log.jsonl").string(), demo.log);
  demo.logPath = (fs::path(directory) / "demo_log.jsonl").string();

  MethodOptions options;
  options.method = Method::MaxMixtureNullHypothesis;
  demo.maxMixture = runMethod(demo.log, options);
  writeMethodRun(folder.path(), demo.maxMixture);
  options.method = Method::Known;
  demo.known = runMethod(demo.log, options);
  writeMethodRun((fs::path(folder.path()) / "known").string(), demo.known);
  folder.commit();
  return demo;
}

}  // namespace semslam
