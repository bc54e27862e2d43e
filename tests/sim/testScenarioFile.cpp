// The aliased2d scenario file: the shipped example equals the built-in default, round trips, defaults for
// omitted fields, and every kind of error named with the file and the problem.

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "SimTesting.h"
#include "semslam/core/InputError.h"
#include "semslam/io/ScenarioFile.h"

namespace semslam {
namespace {

using test::ScratchFolder;

const std::string kExample = std::string(SEMSLAM_SOURCE_DIR) + "/data/scenarios/aliased2d_default.json";

/// A minimal valid scenario with `extra` spliced into the top-level object.
std::string minimalScenario(const std::string& extra = "") {
  return R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
  "objects": [{"id": 3, "class": 1, "pose": [1, 2, 0.5]}],
  "start": [0, 0, 0],
  "motion": {"arena": {"center": [0, 0], "radius": 5}})" +
         extra + "}\n";
}

/// Expects parsing `text` to throw InputError whose message contains every fragment.
void expectError(const std::string& text, std::initializer_list<std::string> fragments, std::size_t line = 0) {
  try {
    parseAliased2dScenario(text, "bad.json");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.file(), "bad.json");
    EXPECT_EQ(error.line(), line) << message;
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
    }
  }
}

TEST(ScenarioFile, TheShippedExampleIsTheBuiltInDefault) {
  const Aliased2dScenario fromFile = readAliased2dScenario(kExample);
  const Aliased2dScenario builtIn = defaultAliased2dScenario();
  EXPECT_TRUE(fromFile == builtIn);
  // And byte for byte what the writer produces for the default.
  EXPECT_EQ(test::fileBytes(kExample), aliased2dScenarioToJson(builtIn));
}

TEST(ScenarioFile, TheDefaultHasPaperAsParameters) {
  const Aliased2dScenario s = defaultAliased2dScenario();
  EXPECT_EQ(s.objects.size(), 6u);                                                  // N = 6
  EXPECT_EQ(s.classes, 2);                                                          // M = 2
  for (const Aliased2dObject& object : s.objects) EXPECT_EQ(object.classIndex, 0);  // one class
  EXPECT_EQ(Vector3(s.priors.objectCovariance.diagonal()), Vector3(0.05, 0.05, 0.5e-3));
  EXPECT_EQ(Vector3(s.priors.initialPoseCovariance.diagonal()), Vector3(100.0, 100.0, 0.04));
  EXPECT_EQ(Vector3(s.motion.covariance.diagonal()), Vector3(0.75e-3, 0.75e-3, 0.25e-3));
  EXPECT_EQ(Vector2(s.sensor.covariance.diagonal()), Vector2(0.1, 0.05));
  for (const Matrix& m : {Matrix(s.priors.objectCovariance), Matrix(s.priors.initialPoseCovariance),
                          Matrix(s.motion.covariance), Matrix(s.sensor.covariance)}) {
    EXPECT_TRUE(m.isDiagonal(0.0));
  }
  EXPECT_EQ(s.alpha, 0.25);
  EXPECT_EQ(s.sharpness, 15.0);
  EXPECT_GT(s.sensor.fieldOfView, 0.0);  // limited field of view
  EXPECT_LT(s.sensor.fieldOfView, std::numbers::pi);
}

TEST(ScenarioFile, WriteReadWriteIsStable) {
  ScratchFolder folder;
  Aliased2dScenario scenario = defaultAliased2dScenario();
  scenario.name = "a \"quoted\" name";
  scenario.alpha = 0.1;
  scenario.priors.poseMean = PoseMean::Sampled;
  scenario.priors.objectMeans = ObjectMeans::Truth;
  scenario.objects[2].pose = SE2(0.1, -0.3, 2.9);
  scenario.motion.covariance(0, 1) = scenario.motion.covariance(1, 0) = 1e-4;
  const std::string path = folder.file("s.json");
  writeAliased2dScenario(path, scenario);
  const Aliased2dScenario read = readAliased2dScenario(path);
  EXPECT_TRUE(read == scenario);
  EXPECT_EQ(aliased2dScenarioToJson(read), test::fileBytes(path));
}

TEST(ScenarioFile, VersionOneFilesAreReadAsTheyWereMeant) {
  // Version 1 had one "means" for both priors, "sampled" by default.
  std::string v1 = minimalScenario();
  v1.replace(v1.find("\"version\": 2"), 12, "\"version\": 1");
  const Aliased2dScenario omitted = parseAliased2dScenario(v1, "v1.json");
  EXPECT_EQ(omitted.priors.poseMean, PoseMean::Sampled);
  EXPECT_EQ(omitted.priors.objectMeans, ObjectMeans::Sampled);
  const Aliased2dScenario truth =
      parseAliased2dScenario(v1.substr(0, v1.rfind('}')) + ", \"priors\": {\"means\": \"truth\"}}", "v1.json");
  EXPECT_EQ(truth.priors.poseMean, PoseMean::Start);
  EXPECT_EQ(truth.priors.objectMeans, ObjectMeans::Truth);
  const Aliased2dScenario v2 = parseAliased2dScenario(minimalScenario(), "v2.json");
  EXPECT_EQ(v2.priors.poseMean, PoseMean::Start);
  EXPECT_EQ(v2.priors.objectMeans, ObjectMeans::Sampled);
}

TEST(ScenarioFile, OmittedFieldsTakeTheDefaultsAndTheNameIsTheStem) {
  ScratchFolder folder;
  const std::string path = folder.file("my_layout.json");
  test::writeText(path, minimalScenario());
  const Aliased2dScenario s = readAliased2dScenario(path);
  const Aliased2dScenario d = defaultAliased2dScenario();
  EXPECT_EQ(s.name, "my_layout");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].id, 3);
  EXPECT_EQ(s.objects[0].classIndex, 1);
  EXPECT_TRUE(s.priors == d.priors);
  EXPECT_TRUE(s.sensor == d.sensor);
  EXPECT_EQ(s.motion.covariance, d.motion.covariance);
  EXPECT_EQ(s.motion.stepLength, d.motion.stepLength);
  EXPECT_EQ(s.motion.arenaRadius, 5.0);
  EXPECT_EQ(s.alpha, d.alpha);
}

TEST(ScenarioFile, FileErrorsNameTheFile) {
  ScratchFolder folder;
  EXPECT_THROW(readAliased2dScenario(folder.file("missing.json")), InputError);
  test::writeText(folder.file("empty.json"), "  \n");
  try {
    readAliased2dScenario(folder.file("empty.json"));
    ADD_FAILURE();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), folder.file("empty.json"));
    EXPECT_NE(std::string(error.what()).find("empty"), std::string::npos);
  }
  EXPECT_THROW(readAliased2dScenario(folder.path().string()), InputError);
}

TEST(ScenarioFile, SyntaxErrorsGiveTheLine) {
  expectError("{\n  \"format\": \"semslam-scenario\",\n  \"version\": 1,,\n}", {"not valid JSON"}, 3);
  expectError(minimalScenario(", \"name\": \"a\", \"name\": \"b\""), {"duplicate key 'name'"}, 4);
}

TEST(ScenarioFile, AKeyProblemInAMultiLineFileGivesTheLineOfTheKey) {
  // Reported at line 0 (the file as a whole) before: the parser does not say where a key is.
  expectError(minimalScenario(",\n  \"name\": \"a \\\"b\\\": {\\\"c\",\n  \"sensor\": {},\n  \"name\": \"b\""),
              {"duplicate key 'name'"}, 7);
  std::string many = "{\"format\": \"semslam-scenario\",\n\"objects\": [{";
  for (int k = 0; k < 1001; ++k) many += (k == 0 ? "\n\"k" : ",\n\"k") + std::to_string(k) + "\": 0";
  expectError(many + "}]}\n", {"more than 1000 keys"}, 1003);
}

TEST(ScenarioFile, StructuralErrorsNameTheField) {
  expectError(minimalScenario(", \"colour\": 1"), {"unknown field 'colour'", "accepted:"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d", "start": [0, 0, 0],
                  "motion": {"arena": {"center": [0, 0], "radius": 5}}})",
              {"missing field 'objects'"});
  expectError(minimalScenario(", \"sensor\": {\"max_range\": \"far\"}"), {"sensor.max_range", "expected a number"});
  expectError(minimalScenario(", \"start\": [0, 0]"), {"duplicate key 'start'"}, 4);
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2]}], "start": [0, 0, 0],
                  "motion": {"arena": {"center": [0, 0], "radius": 5}}})",
              {"objects[0].pose", "expected 3 numbers"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0.5, "pose": [1, 2, 0]}], "start": [0, 0, 0],
                  "motion": {"arena": {"center": [0, 0], "radius": 5}}})",
              {"objects[0].class", "integer"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d", "objects": [],
                  "start": [0, 0, 0], "motion": {"arena": {"center": [0, 0], "radius": 5}}})",
              {"objects", "at least one object"});
  expectError(minimalScenario(", \"sensor\": {\"max_range\": null}"), {"sensor.max_range", "finite"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2, 0]}], "start": [0, 0, 0], "motion": {}})",
              {"motion", "missing field 'arena'"});
}

TEST(ScenarioFile, HeaderErrors) {
  std::string text = minimalScenario();
  expectError(std::string(text).replace(text.find("semslam-scenario"), 16, "semslam-log"),
              {"format", "semslam-scenario"});
  expectError(std::string(text).replace(text.find("\"version\": 2"), 12, "\"version\": 3"),
              {"version 3 is not supported", "versions 1 to 2"});
  expectError(std::string(text).replace(text.find("aliased2d"), 9, "aliased3d"), {"unknown scenario kind"});
}

TEST(ScenarioFile, ValueErrorsNameTheField) {
  expectError(minimalScenario(", \"priors\": {\"object_covariance\": [[1, 0, 0], [0, -1, 0], [0, 0, 1]]}"),
              {"priors.object_covariance", "not positive definite"});
  expectError(minimalScenario(", \"priors\": {\"object_covariance\": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]}"),
              {"priors.object_covariance", "not symmetric"});
  expectError(minimalScenario(", \"priors\": {\"pose_mean\": \"drawn\"}"), {"priors.pose_mean", "start, sampled"});
  expectError(minimalScenario(", \"priors\": {\"object_means\": \"drawn\"}"), {"priors.object_means", "sampled, truth"});
  expectError(minimalScenario(", \"priors\": {\"means\": \"truth\"}"), {"means", "pose_mean", "object_means"});
  expectError(minimalScenario(", \"classes\": 3"), {"classes", "2 classes"});
  expectError(minimalScenario(", \"classifier\": {\"alpha\": 1.5}"), {"classifier.alpha", "[0, 1]"});
  expectError(minimalScenario(", \"classifier\": {\"sharpness\": 0}"), {"classifier.sharpness", "positive"});
  expectError(minimalScenario(", \"sensor\": {\"field_of_view\": 7}"), {"sensor.field_of_view"});
  expectError(minimalScenario(", \"sensor\": {\"max_range\": -1}"), {"sensor.max_range", ">= 0"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2, 0]}, {"id": 0, "class": 0, "pose": [3, 2, 0]}],
                  "start": [0, 0, 0], "motion": {"arena": {"center": [0, 0], "radius": 5}}})",
              {"objects[1].id", "duplicate id 0"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 2, "pose": [1, 2, 0]}],
                  "start": [0, 0, 0], "motion": {"arena": {"center": [0, 0], "radius": 5}}})",
              {"objects[0].class", "[0, 1]"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2, 0]}], "start": [0, 0, 0],
                  "motion": {"step_length": 0, "arena": {"center": [0, 0], "radius": 5}}})",
              {"motion.step_length", "positive"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2, 0]}], "start": [0, 0, 0],
                  "motion": {"max_turn": 4, "arena": {"center": [0, 0], "radius": 5}}})",
              {"motion.max_turn"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2, 0]}], "start": [0, 0, 0],
                  "motion": {"arena": {"center": [0, 0], "radius": 0}}})",
              {"motion.arena.radius", "positive"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2, 0]}], "start": [0, 0, 0],
                  "motion": {"arena": {"center": [0, 0], "radius": 2}, "time_step": -1}})",
              {"motion.time_step", "positive"});
  expectError(R"({"format": "semslam-scenario", "version": 2, "kind": "aliased2d",
                  "objects": [{"id": 0, "class": 0, "pose": [1, 2, 0]}], "start": [0, 0, 0],
                  "motion": {"arena": {"center": [0, 0], "radius": 2}, "clearance": -0.5}})",
              {"motion.clearance", ">= 0"});
}

TEST(ScenarioFile, TheWriterRejectsAnInvalidScenario) {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  scenario.objects[1].id = scenario.objects[0].id;
  EXPECT_THROW(aliased2dScenarioToJson(scenario), std::invalid_argument);
  scenario = defaultAliased2dScenario();
  scenario.sensor.covariance(0, 0) = -1.0;
  EXPECT_THROW(aliased2dScenarioToJson(scenario), std::invalid_argument);
}

TEST(ScenarioFile, HostileNestingAndValuesTheMotionModelWouldIgnoreAreRefused) {
  // 100,000 nested '[' overflowed the parser's stack; a clearance of 1e6 m and an arena radius of 1e-9 m were
  // accepted and silently ignored by the motion model.
  expectError("{\"format\":\n" + std::string(100'000, '['), {"nested deeper than 64"}, 2);
  expectError(R"({"format": "semslam-scenario", "version": 1, "kind": "aliased2d",
  "objects": [{"id": 3, "class": 1, "pose": [1, 2, 0.5]}], "start": [0, 0, 0],
  "motion": {"arena": {"center": [0, 0], "radius": 5}, "clearance": 1e6}})",
              {"motion.clearance", "must be below motion.arena.radius (5), found 1e+06"});
  expectError(R"({"format": "semslam-scenario", "version": 1, "kind": "aliased2d",
  "objects": [{"id": 3, "class": 1, "pose": [1, 2, 0.5]}], "start": [0, 0, 0],
  "motion": {"arena": {"center": [0, 0], "radius": 1e-9}, "clearance": 0}})",
              {"motion.arena.radius", "must be at least motion.step_length (1), found 1e-09"});
}

}  // namespace
}  // namespace semslam
