// `semslam convert isam`: cityTrees10000 counts, square-root information to covariance, ground truth, round trip,
// determinism; and the converter's errors on small hand-written files.

#include <gtest/gtest.h>

#include <cmath>

#include "io/ConverterTesting.h"
#include "semslam/eval/MeasurementResiduals.h"
#include "semslam/io/convert/IsamConverter.h"
#include "support/TestData.h"

using namespace semslam;
using semslam::test::TempDir;

TEST(IsamConverter, CityTreesCountsCovariancesAndTruth) {
  SEMSLAM_REQUIRE_DATA(path, "isam/cityTrees10000.txt");
  ConversionStats stats;
  const MeasurementLog log = convertIsam(path.string(), ConvertOptions{}, &stats);
  // SOURCE.txt: 10000 poses, 100 landmarks, 4443 LANDMARK measurements, 9999 odometry edges; counted here too.
  EXPECT_EQ(log.steps.size(), 10000u);
  EXPECT_EQ(log.steps.size(), test::countTagged(path.string(), "EDGE2") + 1);
  EXPECT_EQ(test::detectionCount(log), 4443u);
  EXPECT_EQ(test::detectionCount(log), test::countTagged(path.string(), "LANDMARK"));
  EXPECT_EQ(log.header.landmarkTruth.size(), 100u);
  EXPECT_EQ(stats.truePoses, 10000u);
  EXPECT_EQ(log.header.sensor.kind, SensorKind::RelativePosition);
  EXPECT_EQ(log.steps[3].time, 3.0);
  // EDGE2 sqrt-information diag(50, 50, 100): covariance diag(1/2500, 1/2500, 1/10000); LANDMARK diag(10, 10).
  const Matrix& odometry = log.steps[1].odometry->covariance;
  EXPECT_NEAR(odometry(0, 0), 1.0 / 2500.0, 1e-15);
  EXPECT_NEAR(odometry(2, 2), 1.0 / 10000.0, 1e-15);
  EXPECT_EQ(odometry(0, 1), 0.0);
  const Detection& first = log.steps[5].detections.front();  // "LANDMARK 5 11 -2.60167 2.61634 10 0 10"
  EXPECT_EQ(*first.truthId, 11);
  EXPECT_EQ(first.geometry(0), -2.60167);
  EXPECT_NEAR(first.covariance(1, 1), 0.01, 1e-15);
  // The simulation's noise is what its square-root information says.
  const LogResidualStatistics residuals = computeResidualStatistics(log);
  for (const auto& c : residuals.detection) EXPECT_NEAR(c.normalizedStd, 1.0, 0.05) << c.name;
  for (const auto& c : residuals.odometry) EXPECT_NEAR(c.normalizedStd, 1.0, 0.05) << c.name;

  TempDir dir;
  MeasurementLog back;
  test::writeAndReadBack(log, dir, "isam.jsonl", &back);
  EXPECT_EQ(back.steps.size(), 10000u);
  EXPECT_EQ(test::detectionCount(back), 4443u);
}

TEST(IsamConverter, SameSeedSameBytes) {
  SEMSLAM_REQUIRE_DATA(path, "isam/cityTrees10000.txt");
  ConvertOptions options;
  options.classes = 4;
  options.misclassification = 0.15;
  options.seed = 99;
  options.mapPriorSigma = 1.0;
  TempDir dir;
  const std::string a = test::writeAndReadBack(convertIsam(path.string(), options), dir, "a.jsonl");
  const std::string b = test::writeAndReadBack(convertIsam(path.string(), options), dir, "b.jsonl");
  EXPECT_TRUE(a == b);
  const MeasurementLog log = convertIsam(path.string(), options);
  EXPECT_EQ(log.header.landmarkPriors.size(), 100u);
  options.seed = 100;
  const std::size_t different = test::expectSameExceptLabels(log, convertIsam(path.string(), options));
  EXPECT_GT(different, 0u);
}

TEST(IsamConverter, SmallFileWithoutGroundTruth) {
  TempDir dir;
  const std::string path = dir.write("tiny.txt",
                                     "EDGE2 0 1 1 0 0 10 0 0 10 0 20\n"
                                     "LANDMARK 1 7 2 1 5 0 5\n"
                                     "LANDMARK 0 7 3 1 5 1 5\n"
                                     "EDGE2 1 2 1 0 0.1 10 0 0 10 0 20\n");
  const MeasurementLog log = convertIsam(path, ConvertOptions{});
  ASSERT_EQ(log.steps.size(), 3u);
  EXPECT_EQ(log.steps[0].detections.size(), 1u);
  EXPECT_EQ(log.steps[1].detections.size(), 1u);
  EXPECT_FALSE(log.steps[0].truePose.has_value());
  EXPECT_TRUE(log.header.landmarkTruth.empty());
  // R = [[5, 1], [0, 5]]: Σ = (RᵀR)⁻¹.
  Matrix2 R;
  R << 5.0, 1.0, 0.0, 5.0;
  const Matrix2 expected = (R.transpose() * R).inverse();
  EXPECT_LT((log.steps[0].detections[0].covariance - expected).cwiseAbs().maxCoeff(), 1e-15);
  test::writeAndReadBack(log, dir, "tiny.jsonl");
}

TEST(IsamConverter, ErrorsNameTheFileAndLine) {
  TempDir dir;
  const std::string outOfOrder = dir.write("order.txt",
                                           "EDGE2 0 1 1 0 0 10 0 0 10 0 20\n"
                                           "EDGE2 2 3 1 0 0 10 0 0 10 0 20\n");
  EXPECT_INPUT_ERROR(convertIsam(outOfOrder, ConvertOptions{}), outOfOrder, 2, "newest pose 1");
  const std::string future = dir.write("future.txt",
                                       "EDGE2 0 1 1 0 0 10 0 0 10 0 20\n"
                                       "LANDMARK 4 1 1 0 1 0 1\n");
  EXPECT_INPUT_ERROR(convertIsam(future, ConvertOptions{}), future, 2, "pose 4");
  const std::string unknown = dir.write("unknown.txt", "EDGE3 0 1 0 0 0 0 0 0\n");
  EXPECT_INPUT_ERROR(convertIsam(unknown, ConvertOptions{}), unknown, 1, "unsupported record type 'EDGE3'");
  const std::string singular = dir.write("singular.txt", "EDGE2 0 1 1 0 0 0 0 0 10 0 20\n");
  EXPECT_INPUT_ERROR(convertIsam(singular, ConvertOptions{}), singular, 1, "singular");
  const std::string missing = dir.path("missing.txt");
  EXPECT_INPUT_ERROR(convertIsam(missing, ConvertOptions{}), missing, 0, "");
}

// Numbers a log may not hold, and rows the ground truth lacks, are refused at the iSAM line that made them (they
// were reported as "step 2" of the log, or at the file as a whole: issue 16).
TEST(IsamConverter, ProblemsOfTheLogAreRefusedAtTheirLine) {
  TempDir dir;
  const std::string edge = "EDGE2 0 1 1 0 0 10 0 0 10 0 20\n";
  const std::string huge = dir.write("huge.txt", edge + "EDGE2 1 2 1e308 0 0 10 0 0 10 0 20\n");
  EXPECT_INPUT_ERROR(convertIsam(huge, ConvertOptions{}), huge, 2, "odometry.increment[0]");
  // A square-root information of 1e-10 is a variance of 1e20.
  const std::string vague = dir.write("vague.txt", edge + edge.substr(0, 6) + "1 2 1 0 0 1e-10 0 0 10 0 20\n");
  EXPECT_INPUT_ERROR(convertIsam(vague, ConvertOptions{}), vague, 2, "odometry.covariance");
  const std::string landmark = dir.write("landmark.txt", edge + "LANDMARK 0 5 1 1 10 0 10\nLANDMARK 1 6 2e7 0 10 0 10\n");
  EXPECT_INPUT_ERROR(convertIsam(landmark, ConvertOptions{}), landmark, 3, "detections[0].geometry[0]");

  // Ground truth beside the file: a landmark it lacks, and a pose file one row short or long.
  const std::string g = dir.write("g.txt", edge + "LANDMARK 0 5 1 1 10 0 10\nLANDMARK 1 6 1 0 10 0 10\n");
  dir.write("g_gt_landmarks_DERIVED.txt", "5 1 1 1\n");
  EXPECT_INPUT_ERROR(convertIsam(g, ConvertOptions{}), g, 3, "landmark 6 is observed but not in");
  dir.write("g_gt_landmarks_DERIVED.txt", "5 1 1 1\n6 2 0 1\n");
  const std::string poses = dir.write("g_gt_poses_DERIVED.txt", "0 0 0 0\n");
  EXPECT_INPUT_ERROR(convertIsam(g, ConvertOptions{}), g, 1, "pose 1 has no row in");
  dir.write("g_gt_poses_DERIVED.txt", "0 0 0 0\n1 1 0 0\n2 2 0 0\n");
  EXPECT_INPUT_ERROR(convertIsam(g, ConvertOptions{}), poses, 3, "pose 2 is not in the iSAM file");
  dir.write("g_gt_poses_DERIVED.txt", "0 0 0 0\n1 2e7 0 0\n");
  EXPECT_INPUT_ERROR(convertIsam(g, ConvertOptions{}), poses, 2, "true_pose[0]");
  dir.write("g_gt_poses_DERIVED.txt", "0 0 0 0\n1 1 0 0\n");
  EXPECT_EQ(convertIsam(g, ConvertOptions{}).steps.size(), 2u);
}
