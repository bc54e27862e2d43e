// Regression replay: every input under fuzz/corpus/<harness>/ and fuzz/findings/<harness>/ (hand-made edge cases,
// and every input a fuzzer ever found) goes through the normal Release readers. The contract, as the libFuzzer
// harnesses hold it: each input parses, or throws InputError; anything else (a crash, another exception) fails
// here. A harness folder without a reader below fails too, so a new corpus is never silently skipped.

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "semslam/core/InputError.h"
#include "semslam/io/EurocFormat.h"
#include "semslam/io/KittiFormat.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/io/TumFormat.h"

namespace semslam {
namespace {

namespace fs = std::filesystem;

using Reader = std::function<void(const std::string& path)>;

const std::map<std::string, Reader>& readers() {
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

const fs::path kFuzz = fs::path(SEMSLAM_SOURCE_DIR) / "fuzz";

TEST(CorpusReplay, EveryInputParsesOrThrowsInputError) {
  std::size_t replayed = 0;
  for (const char* collection : {"corpus", "findings"}) {
    if (!fs::exists(kFuzz / collection)) continue;
    for (const auto& harness : fs::directory_iterator(kFuzz / collection)) {
      const std::string name = harness.path().filename().string();
      const auto reader = readers().find(name);
      ASSERT_NE(reader, readers().end()) << harness.path() << ": no reader for this harness";
      for (const auto& input : fs::directory_iterator(harness.path())) {
        SCOPED_TRACE(input.path().string());
        try {
          reader->second(input.path().string());
        } catch (const InputError&) {
          // the contract: a clear error
        } catch (const std::exception& error) {
          ADD_FAILURE() << "not an InputError: " << error.what();
        }
        ++replayed;
      }
    }
  }
  EXPECT_GE(replayed, readers().size()) << "the corpus is missing";
}

}  // namespace
}  // namespace semslam
