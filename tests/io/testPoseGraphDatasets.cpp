// readPoseGraph on the shared real datasets: record counts and the exact values of a few records.

#include <gtest/gtest.h>

#include <cmath>

#include "IoTesting.h"
#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/io/PoseGraphFile.h"
#include "support/TestData.h"

namespace semslam {
namespace {

template <class F>
const F& factorAs(const PoseGraphFile& file, std::size_t index) {
  const auto* typed = dynamic_cast<const F*>(file.factors[index].get());
  if (typed == nullptr) throw std::runtime_error("factor " + std::to_string(index) + " has another type");
  return *typed;
}

std::size_t countValues(const Values& values, char tag) {
  std::size_t n = 0;
  for (const auto& entry : values) n += Symbol(entry.first).tag() == tag ? 1 : 0;
  return n;
}

TEST(PoseGraphDatasets, ManhattanG2o) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/manhattan/originalDataset/g2o/manhattanOlson3500.g2o");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  EXPECT_EQ(file.initial.size(), 3500u);
  EXPECT_EQ(file.factors.size(), 5598u);
  EXPECT_EQ(file.dimension, 2);
  EXPECT_EQ(file.firstPose, 0u);
  EXPECT_TRUE(file.fixed.empty());
  // VERTEX_SE2 1 1.03039 0.0113498 -0.0129577
  const SE2& x1 = file.initial.at<SE2>(1);
  EXPECT_EQ(x1.x(), 1.03039);
  EXPECT_EQ(x1.y(), 0.0113498);
  EXPECT_NEAR(x1.theta(), -0.0129577, 1e-15);
  // EDGE_SE2 0 1 1.03039 0.0113498 -0.0129577 44.72135955 0 0 44.72135955 0 44.72135955
  const auto& edge = factorAs<BetweenFactor<SE2>>(file, 0);
  EXPECT_EQ(edge.keys(), (std::vector<Key>{0, 1}));
  EXPECT_EQ(edge.measured().x(), 1.03039);
  EXPECT_NEAR(edge.measured().theta(), -0.0129577, 1e-15);
  EXPECT_TRUE(edge.noiseModel()->information().isApprox(44.72135955 * Matrix3::Identity(), 1e-14));
  EXPECT_TRUE(edge.noiseModel()->sqrtInformation().isApprox(std::sqrt(44.72135955) * Matrix3::Identity(), 1e-14));
  // EDGE_SE2 5 9 0.0339432 0.0324387 -3.1274 ... (the first loop closure)
  bool found = false;
  for (std::size_t k = 0; k < file.factors.size() && !found; ++k) {
    const auto& f = factorAs<BetweenFactor<SE2>>(file, k);
    if (f.keys() == std::vector<Key>{5, 9}) {
      found = true;
      EXPECT_EQ(f.measured().y(), 0.0324387);
      EXPECT_NEAR(f.measured().theta(), -3.1274, 1e-15);
    }
  }
  EXPECT_TRUE(found);
}

TEST(PoseGraphDatasets, ManhattanOlsonG2o) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/manhattan/originalDataset/Olson/manhattanOlson3500.g2o");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  EXPECT_EQ(file.initial.size(), 3500u);
  EXPECT_EQ(file.factors.size(), 5598u);
}

TEST(PoseGraphDatasets, Intel) {
  // Vertices and edges interleave in this file; every edge follows the vertices it names.
  SEMSLAM_REQUIRE_DATA(path, "vertigo/intel/originalDataset/intel.g2o");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  EXPECT_EQ(file.initial.size(), 943u);
  EXPECT_EQ(file.factors.size(), 1837u);
  EXPECT_EQ(file.firstPose, 0u);
  EXPECT_NEAR(file.initial.at<SE2>(0).theta(), 1.56834, 1e-15);
}

TEST(PoseGraphDatasets, Ring) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/ring/originalDataset/ring.g2o");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  EXPECT_EQ(file.initial.size(), 434u);
  EXPECT_EQ(file.factors.size(), 459u);
  // EDGE_SE2 0 1 0.950912 0.000000 0.000000 400.000000 0 0 400.000000 0 131.312254
  const auto& edge = factorAs<BetweenFactor<SE2>>(file, 0);
  EXPECT_EQ(edge.measured().x(), 0.950912);
  EXPECT_TRUE(
      edge.noiseModel()->information().isApprox(Vector3(400, 400, 131.312254).asDiagonal().toDenseMatrix(), 1e-14));
}

TEST(PoseGraphDatasets, City10000) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/city10000/originalDataset/city10000.g2o");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  EXPECT_EQ(file.initial.size(), 10000u);
  EXPECT_EQ(file.factors.size(), 20687u);
}

TEST(PoseGraphDatasets, Sphere2500) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/sphere2500/originalDataset/sphere2500.g2o");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  EXPECT_EQ(file.initial.size(), 2500u);
  EXPECT_EQ(file.factors.size(), 4949u);
  EXPECT_EQ(file.dimension, 3);
  EXPECT_EQ(file.firstPose, 0u);
  // VERTEX_SE3:QUAT 1 0.341895 -0.0416997 0.0330394 -0.00189341 0.00395691 0.0899835 0.995934
  const SE3& x1 = file.initial.at<SE3>(1);
  EXPECT_EQ(x1.translation(), Point3(0.341895, -0.0416997, 0.0330394));
  const Eigen::Quaterniond q1 = Eigen::Quaterniond(0.995934, -0.00189341, 0.00395691, 0.0899835).normalized();
  EXPECT_TRUE(x1.rotation().matrix().isApprox(q1.toRotationMatrix(), 1e-14));
  // EDGE_SE3:QUAT 0 1 <pose as above> 10 0 0 0 0 0 10 0 0 0 0 10 0 0 0 400.021 0.00193512 2.06612 399.993
  //   0.496977 99.203
  const auto& edge = factorAs<BetweenFactor<SE3>>(file, 0);
  EXPECT_EQ(edge.keys(), (std::vector<Key>{0, 1}));
  EXPECT_TRUE(edge.measured().equals(x1, 1e-15));
  Matrix6 information = Matrix6::Zero();
  information.diagonal() << 10, 10, 10, 400.021, 399.993, 99.203;
  information(3, 4) = information(4, 3) = 0.00193512;
  information(3, 5) = information(5, 3) = 2.06612;
  information(4, 5) = information(5, 4) = 0.496977;
  EXPECT_TRUE(edge.noiseModel()->information().isApprox(information, 1e-13));
  const Matrix& R = edge.noiseModel()->sqrtInformation();
  EXPECT_TRUE(R.isUpperTriangular());
  EXPECT_NEAR(R(0, 0), std::sqrt(10.0), 1e-14);
  EXPECT_NEAR(R(3, 3), std::sqrt(400.021), 1e-12);
  EXPECT_NEAR(R(3, 4), 0.00193512 / std::sqrt(400.021), 1e-15);
}

TEST(PoseGraphDatasets, W100Toro) {
  SEMSLAM_REQUIRE_DATA(path, "gtsam-examples/w100.graph");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::Toro);
  EXPECT_EQ(file.initial.size(), 100u);
  EXPECT_EQ(file.factors.size(), 300u);  // the 300 EDGE2; the 40 EQUIV add no factor
  ASSERT_EQ(file.equivalences.size(), 40u);
  EXPECT_EQ(file.equivalences.front(), (std::pair<Key, Key>{21, 1}));
  EXPECT_EQ(file.equivalences.back(), (std::pair<Key, Key>{60, 20}));
  EXPECT_EQ(file.firstPose, 0u);
  // VERTEX2 1 0.995595 0.0837204 0.0146728
  EXPECT_EQ(file.initial.at<SE2>(1).y(), 0.0837204);
  // EDGE2 1 0 -0.99879 0.0417574 -0.00818381 1 0 1 1 0 0
  const auto& edge = factorAs<BetweenFactor<SE2>>(file, 0);
  EXPECT_EQ(edge.keys(), (std::vector<Key>{1, 0}));
  EXPECT_EQ(edge.measured().x(), -0.99879);
  EXPECT_TRUE(edge.noiseModel()->information().isApprox(Matrix3::Identity(), 1e-15));
}

TEST(PoseGraphDatasets, ToroInformationOrder) {
  // I_xx I_xy I_yy I_tt I_xt I_yt  →  [I_xx I_xy I_xt; I_xy I_yy I_yt; I_xt I_yt I_tt]
  test::TempDir dir;
  const std::string path = dir.write(
      "order.graph", "VERTEX2 0 0 0 0\nVERTEX 1 1 0 0\nEDGE2 0 1 1 0 0 9 1 8 7 2 3\nEDGE 1 0 -1 0 0 9 1 8 7 2 3\n");
  const PoseGraphFile file = readPoseGraph(path, GraphFormat::Toro);
  ASSERT_EQ(file.factors.size(), 2u);  // TORO's own VERTEX / EDGE tags are read too
  Matrix3 expected;
  expected << 9, 1, 2, 1, 8, 3, 2, 3, 7;
  EXPECT_TRUE(factorAs<BetweenFactor<SE2>>(file, 0).noiseModel()->information().isApprox(expected, 1e-14));
  EXPECT_TRUE(factorAs<BetweenFactor<SE2>>(file, 1).noiseModel()->information().isApprox(expected, 1e-14));
}

TEST(PoseGraphDatasets, ExampleGraphHasUnsupportedBearingRangeRecords) {
  SEMSLAM_REQUIRE_DATA(path, "gtsam-examples/example.graph");
  EXPECT_INPUT_ERROR(readPoseGraph(path.string(), GraphFormat::Toro), path.string(), 190,
                     "unsupported record type 'BR'");
}

TEST(PoseGraphDatasets, CityTrees10000Isam) {
  SEMSLAM_REQUIRE_DATA(path, "isam/cityTrees10000.txt");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::Isam);
  EXPECT_EQ(countValues(file.initial, 'x'), 10000u);
  EXPECT_EQ(countValues(file.initial, 'l'), 100u);
  EXPECT_EQ(file.initial.size(), 10100u);
  EXPECT_EQ(file.factors.size(), 9999u + 4443u);
  EXPECT_EQ(file.firstPose, poseKey(0));
  EXPECT_EQ(file.dimension, 2);

  std::size_t odometry = 0, landmarks = 0;
  for (const FactorPtr& factor : file.factors) {
    odometry += dynamic_cast<const BetweenFactor<SE2>*>(factor.get()) ? 1 : 0;
    landmarks += dynamic_cast<const RelativePointFactor<SE2, Point2>*>(factor.get()) ? 1 : 0;
  }
  EXPECT_EQ(odometry, 9999u);
  EXPECT_EQ(landmarks, 4443u);

  // EDGE2 0 1 -1.01267 -0.00904743 -3.13485 50 0 0 50 0 100  (square-root information)
  const auto& first = factorAs<BetweenFactor<SE2>>(file, 0);
  EXPECT_EQ(first.keys(), (std::vector<Key>{poseKey(0), poseKey(1)}));
  EXPECT_EQ(first.measured().x(), -1.01267);
  EXPECT_TRUE(first.noiseModel()->sqrtInformation().isApprox(Vector3(50, 50, 100).asDiagonal().toDenseMatrix(), 1e-15));
  EXPECT_TRUE(
      first.noiseModel()->information().isApprox(Vector3(2500, 2500, 10000).asDiagonal().toDenseMatrix(), 1e-15));
  EXPECT_TRUE(file.initial.at<SE2>(poseKey(0)).equals(SE2(), 0.0));
  EXPECT_TRUE(file.initial.at<SE2>(poseKey(1)).equals(first.measured(), 1e-15));

  // Line 6: LANDMARK 5 11 -2.60167 2.61634 10 0 10, the first observation of l11.
  const auto& landmark = factorAs<RelativePointFactor<SE2, Point2>>(file, 5);
  EXPECT_EQ(landmark.keys(), (std::vector<Key>{poseKey(5), landmarkKey(11)}));
  EXPECT_EQ(landmark.measured(), Point2(-2.60167, 2.61634));
  EXPECT_TRUE(landmark.noiseModel()->sqrtInformation().isApprox(10.0 * Matrix2::Identity(), 1e-15));
  EXPECT_TRUE(landmark.noiseModel()->information().isApprox(100.0 * Matrix2::Identity(), 1e-15));
  const Point2 expected = file.initial.at<SE2>(poseKey(5)).transformFrom(Point2(-2.60167, 2.61634));
  EXPECT_TRUE(file.initial.at<Point2>(landmarkKey(11)).isApprox(expected, 1e-15));
}

TEST(PoseGraphDatasets, IsamFileReadAsToroPointsAtTheFormat) {
  SEMSLAM_REQUIRE_DATA(path, "isam/cityTrees10000.txt");
  EXPECT_INPUT_ERROR(readPoseGraph(path.string(), GraphFormat::Toro), path.string(), 1, "read them as isam");
}

}  // namespace
}  // namespace semslam
