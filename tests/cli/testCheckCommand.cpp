// `semslam check LOG`: a summary and exit 0 for a valid measurement log, exit 2 naming file, line and problem for
// a malformed one.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/RunCommand.h"

using semslam::test::runSemslam;

namespace {

class CheckDir {
 public:
  CheckDir() : path_(std::filesystem::temp_directory_path() / ("semslam_check_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~CheckDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name, const std::string& contents) const {
    const auto path = path_ / name;
    std::ofstream(path, std::ios::binary) << contents;
    return path.string();
  }

 private:
  std::filesystem::path path_;
};

const std::string kHeader =
    R"({"format":"semslam-log","version":1,"dimension":2,"classes":3,"semantic":"label",)"
    R"("classifier":{"kind":"categorical","misclassification":0.1},)"
    R"("sensor":{"kind":"range-bearing","max_range":10.0},"landmarks_have_pose":false,)"
    R"("landmark_truth":[{"id":0,"class":1,"position":[2.0,1.0]},{"id":1,"position":[5.0,-1.0]}]})";
const std::string kOdometry =
    R"("odometry":{"increment":[1.0,0.0,0.1],"covariance":[[0.01,0,0],[0,0.01,0],[0,0,0.001]]})";
const std::string kStep0 =
    R"({"time":10.0,"detections":[{"geometry":[2.2,0.46],"covariance":[[0.01,0],[0,0.001]],"label":1,"truth":0}]})";
const std::string kStep1 = R"({"time":10.5,)" + kOdometry +
                           R"(,"detections":[{"geometry":[4.1,-0.3],"covariance":[[0.01,0],[0,0.001]],"label":2,)"
                           R"("truth":1},{"geometry":[3.0,1.0],"covariance":[[0.01,0],[0,0.001]],"label":0,)"
                           R"("truth":"not-a-landmark"},{"geometry":[1.0,1.0],"covariance":[[0.01,0],[0,0.001]],)"
                           R"("label":0}]})";
const std::string kStep2 = R"({"time":12.0,)" + kOdometry + R"(,"detections":[],"true_pose":[2.0,0.0,0.2]})";

}  // namespace

TEST(CheckCommand, PrintsTheSummaryOfAValidLog) {
  CheckDir dir;
  const std::string log = dir.file("good.jsonl", kHeader + "\n" + kStep0 + "\n" + kStep1 + "\n" + kStep2 + "\n");
  const auto run = runSemslam("check " + log);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const char* expected : {
           "good.jsonl: valid semslam-log, version 1",
           "dimension:     2D, landmarks are points",
           "sensor:        range-bearing, max range 10 m, all around",
           "classes:       3, semantic label, classifier categorical (misclassification 0.1)",
           "steps:         3 (2 with odometry, 1 with a true pose)",
           "duration:      2 s (time 10 to 12)",
           "detections:    4; per step min 0, mean 1.333, max 3",
           "ground truth:  2 landmarks; 3 detections with truth (2 of a landmark, 1 clutter, 0 unknown), 1 without",
           "priors:        initial pose no; 0 landmark priors",
       }) {
    EXPECT_NE(run.output.find(expected), std::string::npos) << "missing \"" << expected << "\" in:\n" << run.output;
  }
}

TEST(CheckCommand, CountsUnknownTruthAndLeavesItOutOfTheResiduals) {
  // Version 2: the third detection of step 1 has truth "unknown" (docs/measurement-log.md, "Detections").
  CheckDir dir;
  std::string header = kHeader;
  header.replace(header.find(R"("version":1)"), 11, R"("version":2)");
  std::string step1 = kStep1;
  step1.replace(step1.find(R"("label":0}]})"), 12, R"("label":0,"truth":"unknown"}]})");
  const std::string log = dir.file("unknown.jsonl", header + "\n" + kStep0 + "\n" + step1 + "\n" + kStep2 + "\n");
  const auto run = runSemslam("check --residuals " + log);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("valid semslam-log, version 2"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("4 detections with truth (2 of a landmark, 1 clutter, 1 unknown), 0 without"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("1 clutter, 1 unknown truth, 2 without a true pose"), std::string::npos) << run.output;
  // The odometry over windows: one true pose only, so no window has both ends (eval/MeasurementResiduals.h).
  EXPECT_NE(run.output.find("odometry over windows of n steps"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("           1                 0       0.000       0.000"), std::string::npos) << run.output;

  // The same detection in a version-1 file is an error naming the line.
  std::string old = header;
  old.replace(old.find(R"("version":2)"), 11, R"("version":1)");
  const auto rejected = runSemslam("check " + dir.file("old.jsonl", old + "\n" + kStep0 + "\n" + step1 + "\n"));
  EXPECT_EQ(rejected.exitCode, 2) << rejected.output;
  EXPECT_NE(rejected.output.find("old.jsonl:3: detections[2].truth: \"unknown\" truth needs version 2"),
            std::string::npos)
      << rejected.output;
}

TEST(CheckCommand, MalformedLogExitsWithCodeTwoNamingFileLineAndProblem) {
  CheckDir dir;
  struct Case {
    const char* name;
    std::string contents;
    const char* expected;
  };
  std::string notPd = kStep1;
  notPd.replace(notPd.find("[0,0.01,0]"), 10, "[0,-0.01,0]");
  const std::vector<Case> cases = {
      {"time.jsonl", kHeader + "\n" + kStep0 + "\n" + kStep1 + "\n" + R"({"time":10.5,)" + kOdometry +
                         R"(,"detections":[]})" + "\n",
       ":4: time: time 10.5 is not after the previous step's time 10.5"},
      {"not_pd.jsonl", kHeader + "\n" + kStep0 + "\n" + notPd + "\n", ":3: odometry.covariance: not positive definite"},
      {"typo.jsonl", kHeader + "\n" + R"({"time":0,"detection":[]})" + "\n", ":2: unknown field 'detection'"},
      {"truncated.jsonl", kHeader + "\n" + kStep0.substr(0, 30) + "\n", ":2: not valid JSON"},
      {"empty.jsonl", "", "empty.jsonl: the file is empty"},
      {"header_only.jsonl", kHeader + "\n", "no time steps"},
  };
  for (const Case& c : cases) {
    const auto run = runSemslam("check " + dir.file(c.name, c.contents));
    EXPECT_EQ(run.exitCode, 2) << c.name << ": " << run.output;
    EXPECT_NE(run.output.find(std::string(c.name) + ":"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.name << ": " << run.output;
    EXPECT_EQ(run.output.find("valid semslam-log"), std::string::npos) << run.output;
  }
  const auto missing = runSemslam("check " + dir.file("x", "") + ".does-not-exist");
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  EXPECT_NE(missing.output.find("file does not exist"), std::string::npos) << missing.output;
  const auto noArgument = runSemslam("check");
  EXPECT_EQ(noArgument.exitCode, 2) << noArgument.output;
}
