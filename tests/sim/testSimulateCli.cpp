// `semslam simulate`: the same seed gives the same bytes across runs of the tool, several tracks go to a
// folder of track_NNN.jsonl, --write-scenario reproduces the shipped example, and bad input exits with 2.

#include <gtest/gtest.h>

#include <filesystem>

#include "../support/RunCommand.h"
#include "../support/TestData.h"
#include "SimTesting.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/ScenarioFile.h"

namespace semslam {
namespace {

using test::runSemslam;
using test::ScratchFolder;

std::string quoted(const std::string& path) { return "\"" + path + "\""; }

TEST(SimulateCli, Aliased2dIsDeterministicAcrossRuns) {
  ScratchFolder folder;
  const std::string a = folder.file("a.jsonl"), b = folder.file("b.jsonl"), c = folder.file("c.jsonl");
  auto result = runSemslam("simulate aliased2d --steps 30 --seed 5 --out " + quoted(a));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  result = runSemslam("simulate aliased2d --steps 30 --seed 5 --out " + quoted(b));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  result = runSemslam("simulate aliased2d --steps 30 --seed 6 --out " + quoted(c));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(test::fileBytes(a), test::fileBytes(b));
  EXPECT_NE(test::fileBytes(a), test::fileBytes(c));
  EXPECT_EQ(readMeasurementLog(a).steps.size(), 31u);
}

TEST(SimulateCli, SeveralTracksGoToAFolder) {
  ScratchFolder folder;
  const std::string out = folder.file("tracks");
  const auto result = runSemslam("simulate aliased2d --tracks 12 --steps 10 --out " + quoted(out));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("simulate aliased2d tracks: 12/12"), std::string::npos)
      << result.output;  // progress (core/ProgressBar.h: its last line off a terminal)
  for (int track = 0; track < 12; ++track) {
    char name[32];
    std::snprintf(name, sizeof name, "track_%03d.jsonl", track);
    const std::string path = (std::filesystem::path(out) / name).string();
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    EXPECT_EQ(readMeasurementLog(path).steps.size(), 11u);
  }
  // Track 3 of the run is the same log whichever way it is asked for.
  const std::string again = folder.file("again");
  ASSERT_EQ(runSemslam("simulate aliased2d --tracks 12 --steps 10 --out " + quoted(again)).exitCode, 0);
  EXPECT_EQ(test::fileBytes(out + "/track_003.jsonl"), test::fileBytes(again + "/track_003.jsonl"));
}

TEST(SimulateCli, ALayoutSeedGivesTheGeneratedLayoutAndExcludesAScenarioFile) {
  ScratchFolder folder;
  const std::string written = folder.file("layout1.json");
  const auto result = runSemslam("simulate aliased2d --layout-seed 1 --write-scenario " + quoted(written));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(test::fileBytes(written),
            test::fileBytes(std::string(SEMSLAM_SOURCE_DIR) + "/data/scenarios/aliased2d_layout_1.json"));
  // The layout's tracks are those of its scenario file.
  const std::string fromSeed = folder.file("seed.jsonl"), fromFile = folder.file("file.jsonl");
  ASSERT_EQ(runSemslam("simulate aliased2d --layout-seed 1 --steps 5 --out " + quoted(fromSeed)).exitCode, 0);
  ASSERT_EQ(runSemslam("simulate aliased2d --scenario " + quoted(written) + " --steps 5 --out " + quoted(fromFile))
                .exitCode,
            0);
  EXPECT_EQ(test::fileBytes(fromSeed), test::fileBytes(fromFile));
  const auto both = runSemslam("simulate aliased2d --layout-seed 1 --scenario " + quoted(written) + " --out " +
                               quoted(folder.file("both.jsonl")));
  EXPECT_NE(both.exitCode, 0);
  EXPECT_NE(both.output.find("excludes"), std::string::npos) << both.output;
}

TEST(SimulateCli, The3dLiftsWriteLogsThatReadBack) {
  // The lifts' defaults must make logs the format accepts (a level σ within its conditioning bound of the 10 m
  // start prior), with and without object heights, and the same seed the same bytes.
  ScratchFolder folder;
  const std::string level = folder.file("level.jsonl"), heights = folder.file("heights.jsonl"),
                    again = folder.file("again.jsonl");
  auto result = runSemslam("simulate aliased2d --steps 8 --seed 3 --lift-3d --out " + quoted(level));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string withHeights = "simulate aliased2d --steps 8 --seed 3 --object-heights 0,0.4,0.8,0,0.4,0.8 --out ";
  result = runSemslam(withHeights + quoted(heights));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  ASSERT_EQ(runSemslam(withHeights + quoted(again)).exitCode, 0);
  EXPECT_EQ(test::fileBytes(heights), test::fileBytes(again));
  for (const std::string& path : {level, heights}) {
    const MeasurementLog log = readMeasurementLog(path);
    EXPECT_EQ(log.header.dimension, 3) << path;
    EXPECT_EQ(log.steps.size(), 9u) << path;
  }
}

TEST(SimulateCli, WriteScenarioReproducesTheShippedExample) {
  ScratchFolder folder;
  const std::string written = folder.file("default.json");
  auto result = runSemslam("simulate aliased2d --write-scenario " + quoted(written));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(test::fileBytes(written),
            test::fileBytes(std::string(SEMSLAM_SOURCE_DIR) + "/data/scenarios/aliased2d_default.json"));
  // Simulating from the file gives the same bytes as from the built-in default.
  const std::string fromFile = folder.file("file.jsonl"), builtIn = folder.file("builtin.jsonl");
  ASSERT_EQ(runSemslam("simulate aliased2d --scenario " + quoted(written) + " --out " + quoted(fromFile)).exitCode, 0);
  ASSERT_EQ(runSemslam("simulate aliased2d --out " + quoted(builtIn)).exitCode, 0);
  EXPECT_EQ(test::fileBytes(fromFile), test::fileBytes(builtIn));
  // --alpha reaches the log.
  const std::string alpha = folder.file("alpha.jsonl");
  ASSERT_EQ(runSemslam("simulate aliased2d --alpha 0.5 --out " + quoted(alpha)).exitCode, 0);
  EXPECT_EQ(readMeasurementLog(alpha).header.classifier.alpha, 0.5);
}

TEST(SimulateCli, BadInputExitsWithTwo) {
  ScratchFolder folder;
  const std::string scenario = folder.file("bad.json");
  test::writeText(scenario, "{\"format\": \"semslam-scenario\"}");
  auto result = runSemslam("simulate aliased2d --scenario " + quoted(scenario) + " --out " + quoted(folder.file("x")));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("bad.json"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("missing field"), std::string::npos) << result.output;
  result = runSemslam("simulate aliased2d --alpha 3 --out " + quoted(folder.file("x")));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  result = runSemslam("simulate aliased2d");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  result = runSemslam("simulate semantic --misclassification 1.5 --out " + quoted(folder.file("y")));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  result = runSemslam("simulate semantic --trajectory " + quoted(scenario) + " --out " + quoted(folder.file("y")));
  EXPECT_EQ(result.exitCode, 2) << result.output;  // no --trajectory-format
  result = runSemslam("simulate semantic --trajectory " + quoted(scenario) + " --trajectory-format tum --out " +
                      quoted(folder.file("y")));
  EXPECT_EQ(result.exitCode, 2) << result.output;  // not a TUM file
}

TEST(SimulateCli, SemanticIsDeterministicAcrossRuns) {
  ScratchFolder folder;
  for (const std::string& options : {std::string("--dimension 2 --clutter 1"),
                                     std::string("--dimension 3 --path lawnmower --misclassification 0.3")}) {
    const std::string a = folder.file("a.jsonl"), b = folder.file("b.jsonl");
    ASSERT_EQ(runSemslam("simulate semantic " + options + " --seed 9 --out " + quoted(a)).exitCode, 0);
    ASSERT_EQ(runSemslam("simulate semantic " + options + " --seed 9 --out " + quoted(b)).exitCode, 0);
    EXPECT_EQ(test::fileBytes(a), test::fileBytes(b)) << options;
    ASSERT_EQ(runSemslam("simulate semantic " + options + " --seed 10 --out " + quoted(b)).exitCode, 0);
    EXPECT_NE(test::fileBytes(a), test::fileBytes(b)) << options;
  }
}

TEST(SimulateCli, SemanticShowsProgressUnlessQuiet) {
  ScratchFolder folder;
  const std::string out = folder.file("p.jsonl");
  const auto shown = runSemslam("simulate semantic --steps 50 --out " + quoted(out));
  ASSERT_EQ(shown.exitCode, 0) << shown.output;
  EXPECT_NE(shown.output.find("simulate semantic: 51/51"), std::string::npos) << shown.output;
  const auto quiet = runSemslam("simulate semantic --steps 50 --quiet --out " + quoted(out));
  ASSERT_EQ(quiet.exitCode, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("simulate semantic:"), std::string::npos) << quiet.output;
}

TEST(SimulateCli, SemanticFromKitti) {
  SEMSLAM_REQUIRE_DATA(file, "kitti-odometry-poses/00.txt");
  ScratchFolder folder;
  const std::string out = folder.file("kitti.jsonl");
  const auto result =
      runSemslam("simulate semantic --dimension 3 --trajectory " + quoted(file.string()) +
                 " --trajectory-format kitti --stride 5 --steps 400 --max-range 30 --out " + quoted(out));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const MeasurementLog log = readMeasurementLog(out);
  EXPECT_EQ(log.steps.size(), 401u);
  EXPECT_EQ(log.header.dimension, 3);
  EXPECT_NE(log.header.source.find("00.txt"), std::string::npos);
}

}  // namespace
}  // namespace semslam
