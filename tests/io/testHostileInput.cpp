// Hostile input to every reader: what crashed, ran unbounded or echoed megabytes before is refused with an
// InputError naming the file and line, quickly and in bounded memory (issue 16).

#include <gtest/gtest.h>

#include <string>

#include "IoTesting.h"
#include "semslam/core/InputFile.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/io/TrajectoryFormat.h"

namespace semslam {
namespace {

using test::TempDir;

const std::string kHeader =
    R"({"format":"semslam-log","version":1,"dimension":2,"classes":3,"semantic":"label",)"
    R"("classifier":{"kind":"categorical","misclassification":0.1},)"
    R"("sensor":{"kind":"range-bearing","body_to_sensor":[0.1,0.0,0.0],"max_range":10.0,"field_of_view":3.0},)"
    R"("landmarks_have_pose":false,"initial_pose":{"mean":[0.0,0.0,0.0],)"
    R"("covariance":[[1e-4,0,0],[0,1e-4,0],[0,0,1e-6]]}})";
const std::string kStep = R"({"time":0.0,"detections":[]})";
const std::string kDetection = R"({"geometry":[2.2,0.46],"covariance":[[0.01,0],[0,0.001]],"label":1})";

TEST(HostileInput, AHundredThousandNestedBracketsInALogHeaderOrStepAreRefusedNotACrash) {
  const TempDir dir;
  const std::string deep(100'000, '[');
  const std::string header = dir.write("header.jsonl", deep + "\n" + kStep + "\n");
  EXPECT_INPUT_ERROR(readMeasurementLog(header), header, 1, "nested deeper than 64");
  const std::string step = dir.write("step.jsonl", kHeader + "\n" + kStep + "\n" + R"({"time":1,"x":)" + deep + "\n");
  EXPECT_INPUT_ERROR(readMeasurementLog(step), step, 3, "nested deeper than 64");
}

TEST(HostileInput, AHeaderWithAHundredThousandKeysIsRefusedQuickly) {
  // The duplicate-key scan was quadratic: 100k distinct keys took more than 20 s.
  const TempDir dir;
  std::string header = "{";
  for (int k = 0; k < 100'000; ++k) header += "\"k" + std::to_string(k) + "\":0,";
  header += "\"last\":0}";
  const std::string path = dir.write("keys.jsonl", header + "\n" + kStep + "\n");
  EXPECT_INPUT_ERROR(readMeasurementLog(path), path, 1, "more than 1000 keys");
}

TEST(HostileInput, MoreDetectionsInOneStepThanTheLimitAreRefused) {
  // 300,000 detections on one line took more than 20 s (nlohmann's callback parser is quadratic in an array of
  // objects; 200,000 took 18 s): now a linear SAX pass and the plain parser, then the count.
  const TempDir dir;
  for (const int count : {10'001, 200'000}) {
    std::string detections;
    for (int k = 0; k < count; ++k) detections += (k == 0 ? "" : ",") + kDetection;
    const std::string path =
        dir.write("many.jsonl", kHeader + "\n" + R"({"time":0.0,"detections":[)" + detections + "]}\n");
    EXPECT_INPUT_ERROR(readMeasurementLog(path), path, 2,
                       std::to_string(count) + " detections in one step (at most 10000)");
  }
}

TEST(HostileInput, AMillionClassesAreRefusedBeforeAnyConfusionMatrixIsAllocated) {
  const TempDir dir;
  std::string header = kHeader;
  header.replace(header.find("\"classes\":3"), 11, "\"classes\":1000000");
  const std::string path = dir.write("classes.jsonl", header + "\n" + kStep + "\n");
  EXPECT_INPUT_ERROR(readMeasurementLog(path), path, 1, "classes");
}

TEST(HostileInput, AnOverlongLineIsRefusedWithItsLine) {
  const TempDir dir;
  const std::string path = dir.write("long.jsonl", kHeader + "\n" + std::string(kMaxInputLineBytes + 1, ' ') + "\n");
  EXPECT_INPUT_ERROR(readMeasurementLog(path), path, 2, "line longer than 16 MiB");
}

TEST(HostileInput, DevicesAreRefusedByEveryReaderBeforeTheyAreRead) {
  // optimize /dev/zero read until memory ran out.
  EXPECT_INPUT_ERROR(readPoseGraph("/dev/zero", GraphFormat::G2o), "/dev/zero", 0, "not a regular file");
  EXPECT_INPUT_ERROR(readMeasurementLog("/dev/zero"), "/dev/zero", 0, "not a regular file");
  EXPECT_INPUT_ERROR(readTrajectory("/dev/zero", TrajectoryFormat::Tum), "/dev/zero", 0, "not a regular file");
  EXPECT_INPUT_ERROR(readAliased2dScenario("/dev/zero"), "/dev/zero", 0, "not a regular file");
}

TEST(HostileInput, AHugeTokenIsQuotedAsAShortEscapedExcerpt) {
  const TempDir dir;
  const std::string token = "\x1b[31m" + std::string(1'000'000, '9') + "x";
  const std::string path = dir.write("token.g2o", "VERTEX_SE2 0 " + token + " 0 0\n");
  try {
    readPoseGraph(path, GraphFormat::G2o);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_LT(message.size(), 400u) << message.substr(0, 400);
    EXPECT_EQ(message.find('\x1b'), std::string::npos);
    EXPECT_NE(message.find("'\\x1b[31m999"), std::string::npos) << message;
    EXPECT_NE(message.find("(1000006 bytes)"), std::string::npos) << message;
  }
}

TEST(HostileInput, AHugeJsonTokenIsQuotedAsAShortExcerpt) {
  const TempDir dir;
  const std::string path =
      dir.write("token.jsonl", kHeader + "\n" + R"({"time":)" + std::string(1'000'000, 'z') + "\n");
  try {
    readMeasurementLog(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 2u);
    EXPECT_LT(std::string(error.what()).size(), 400u);
  }
}

}  // namespace
}  // namespace semslam
