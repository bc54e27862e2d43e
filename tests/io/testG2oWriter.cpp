// writeG2o: the records it writes, write → read round trips, the g2o numbering of typed keys, and atomic output.

#include <gtest/gtest.h>

#include <filesystem>

#include "IoTesting.h"
#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/io/G2oIds.h"
#include "semslam/io/PoseGraphFile.h"
#include "support/TestData.h"

namespace semslam {
namespace {

using test::readText;
using test::TempDir;

/// A full (non-diagonal) symmetric positive definite matrix of size n.
Matrix spdMatrix(int n, double seed) {
  Matrix a(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) a(i, j) = std::sin(seed * (1 + i) + 0.7 * j * j + 0.3);
  }
  return a * a.transpose() + n * Matrix::Identity(n, n);
}

/// Expects the two graphs to hold the same edges, with keys mapped by `keyOf`, to 1e-12.
template <class KeyOf>
void expectSameEdges(const FactorGraph& written, const FactorGraph& read, KeyOf keyOf) {
  std::size_t k = 0;
  for (const FactorPtr& factor : written) {
    const auto* between2 = dynamic_cast<const BetweenFactor<SE2>*>(factor.get());
    const auto* point = dynamic_cast<const RelativePointFactor<SE2, Point2>*>(factor.get());
    const auto* between3 = dynamic_cast<const BetweenFactor<SE3>*>(factor.get());
    if (!between2 && !point && !between3) continue;  // not a g2o record
    ASSERT_LT(k, read.size());
    const Factor& other = *read[k++];
    ASSERT_EQ(other.keys().size(), 2u);
    EXPECT_EQ(other.keys()[0], keyOf(factor->keys()[0]));
    EXPECT_EQ(other.keys()[1], keyOf(factor->keys()[1]));
    if (between2) {
      const auto& back = dynamic_cast<const BetweenFactor<SE2>&>(other);
      EXPECT_TRUE(back.measured().equals(between2->measured(), 1e-12));
      EXPECT_TRUE(back.noiseModel()->information().isApprox(between2->noiseModel()->information(), 1e-12));
      EXPECT_TRUE(back.noiseModel()->sqrtInformation().isApprox(between2->noiseModel()->sqrtInformation(), 1e-12));
    } else if (point) {
      const auto& back = dynamic_cast<const RelativePointFactor<SE2, Point2>&>(other);
      EXPECT_TRUE(back.measured().isApprox(point->measured(), 1e-12));
      EXPECT_TRUE(back.noiseModel()->information().isApprox(point->noiseModel()->information(), 1e-12));
    } else {
      const auto& back = dynamic_cast<const BetweenFactor<SE3>&>(other);
      EXPECT_TRUE(back.measured().equals(between3->measured(), 1e-12));
      EXPECT_TRUE(back.noiseModel()->information().isApprox(between3->noiseModel()->information(), 1e-12));
    }
  }
  EXPECT_EQ(k, read.size());
}

void expectSameValue(const Value& a, const Value& b) {
  ASSERT_EQ(a.index(), b.index());
  if (const auto* p = std::get_if<SE2>(&a)) {
    EXPECT_TRUE(p->equals(std::get<SE2>(b), 1e-12));
  } else if (const auto* p3 = std::get_if<SE3>(&a)) {
    EXPECT_TRUE(p3->equals(std::get<SE3>(b), 1e-12));
  } else {
    EXPECT_TRUE(std::get<Point2>(a).isApprox(std::get<Point2>(b), 1e-12));
  }
}

TEST(G2oWriter, WritesTheExpectedRecords) {
  TempDir dir;
  Values values;
  values.insert(0, SE2(0, 0, 0));
  values.insert(1, SE2(1.5, -2, 0.25));
  values.insert(2, Point2(0.1, 3));
  FactorGraph graph;
  Matrix3 information;
  information << 4, 2, 0, 2, 10, 0, 0, 0, 1;  // R = [2 1 0; 0 3 0; 0 0 1], so RᵀR is exact
  graph.emplace<PriorFactor<SE2>>(0, SE2(), NoiseModel::isotropic(3, 1.0));  // not a g2o record: skipped
  graph.emplace<BetweenFactor<SE2>>(0, 1, SE2(1.5, -2, 0.25), NoiseModel::fromInformation(information));
  graph.emplace<RelativePointFactor<SE2, Point2>>(1, 2, Point2(0.5, 0.25), NoiseModel::fromSigmas(Vector2(0.5, 2)));
  const std::string path = dir.path("out.g2o");
  writeG2o(path, graph, values, {0});
  EXPECT_EQ(readText(path),
            "VERTEX_SE2 0 0 0 0\n"
            "VERTEX_SE2 1 1.5 -2 0.25\n"
            "VERTEX_XY 2 0.1 3\n"
            "FIX 0\n"
            "EDGE_SE2 0 1 1.5 -2 0.25 4 2 0 10 0 1\n"
            "EDGE_SE2_XY 1 2 0.5 0.25 4 0 0.25\n");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(G2oWriter, RoundTrip2D) {
  TempDir dir;
  Values values;
  FactorGraph graph;
  for (int i = 0; i < 6; ++i) values.insert(i, SE2(0.1 * i * i, std::cos(i) / 3.0, 0.4 * i - 1.1));
  values.insert(10, Point2(1.0 / 3.0, -2.0 / 7.0));
  values.insert(11, Point2(1e-300, 12345.678901234567));
  for (int i = 0; i + 1 < 6; ++i) {
    graph.emplace<BetweenFactor<SE2>>(i, i + 1, SE2(1.0 / (i + 3), -0.1 * i, 2.9),
                                      NoiseModel::fromInformation(spdMatrix(3, i)));
  }
  graph.emplace<BetweenFactor<SE2>>(5, 0, SE2(0.3, 0.2, -3.1), NoiseModel::fromInformation(spdMatrix(3, 9)));
  graph.emplace<RelativePointFactor<SE2, Point2>>(2, 10, Point2(0.7, 1.0 / 9.0),
                                                  NoiseModel::fromInformation(spdMatrix(2, 4)));
  graph.emplace<RelativePointFactor<SE2, Point2>>(4, 11, Point2(-5, 2), NoiseModel::fromSigmas(Vector2(0.1, 0.3)));
  const std::string path = dir.path("two.g2o");
  writeG2o(path, graph, values, {0, 3, 0});

  const PoseGraphFile back = readPoseGraph(path, GraphFormat::G2o);
  ASSERT_EQ(back.initial.size(), values.size());
  for (const auto& [key, value] : values) expectSameValue(back.initial.value(key), value);
  expectSameEdges(graph, back.factors, [](Key key) { return key; });
  EXPECT_EQ(back.fixed, (std::vector<Key>{0, 3}));  // a vertex fixed twice is read once
  EXPECT_EQ(back.firstPose, 0u);
}

TEST(G2oWriter, RoundTrip3D) {
  TempDir dir;
  Values values;
  FactorGraph graph;
  for (int i = 0; i < 4; ++i) {
    const SO3 rotation = SO3::fromAxisAngle(Vector3(1, -2 * i, 0.5), 0.9 * i - 1.3);
    values.insert(7 + i, SE3(rotation, Point3(i / 3.0, -i * 1.1, 2.0 / (i + 1))));
  }
  for (int i = 0; i < 3; ++i) {
    const SE3 z(SO3::fromAxisAngle(Vector3(0.2, 1, -i), 0.5 + i), Point3(1.0 / 7.0, i, -0.3));
    graph.emplace<BetweenFactor<SE3>>(7 + i, 8 + i, z, NoiseModel::fromInformation(spdMatrix(6, i + 0.5)));
  }
  const std::string path = dir.path("three.g2o");
  writeG2o(path, graph, values);
  const PoseGraphFile back = readPoseGraph(path, GraphFormat::G2o);
  EXPECT_EQ(back.dimension, 3);
  EXPECT_EQ(back.firstPose, 7u);
  ASSERT_EQ(back.initial.size(), values.size());
  for (const auto& [key, value] : values) expectSameValue(back.initial.value(key), value);
  expectSameEdges(graph, back.factors, [](Key key) { return key; });
}

TEST(G2oWriter, RoundTripOfRealFiles) {
  SEMSLAM_REQUIRE_DATA(manhattan, "vertigo/manhattan/originalDataset/g2o/manhattanOlson3500.g2o");
  SEMSLAM_REQUIRE_DATA(sphere, "vertigo/sphere2500/originalDataset/sphere2500.g2o");
  TempDir dir;
  for (const auto& source : {manhattan, sphere}) {
    const PoseGraphFile file = readPoseGraph(source.string(), GraphFormat::G2o);
    const std::string path = dir.path("copy.g2o");
    writeG2o(path, file.factors, file.initial, file.fixed);
    const PoseGraphFile back = readPoseGraph(path, GraphFormat::G2o);
    ASSERT_EQ(back.initial.size(), file.initial.size());
    for (const auto& [key, value] : file.initial) expectSameValue(back.initial.value(key), value);
    expectSameEdges(file.factors, back.factors, [](Key key) { return key; });
  }
}

TEST(G2oWriter, IsamKeysAreNumbered) {
  TempDir dir;
  const std::string isam = dir.write("city.txt",
                                     "EDGE2 0 1 1 0 0.1  10 0 0 10 0 20\n"
                                     "EDGE2 1 2 1 0 0.2  10 0 0 10 0 20\n"
                                     "LANDMARK 2 7 1 1  5 0 5\n"
                                     "LANDMARK 1 3 2 -1  5 0.5 5\n");
  const PoseGraphFile file = readPoseGraph(isam, GraphFormat::Isam);
  const std::string path = dir.path("city.g2o");
  writeG2o(path, file.factors, file.initial);
  // x0 x1 x2 keep ids 0 1 2; the landmarks follow in key order: l3 → 3, l7 → 4.
  const auto idOf = [](Key key) -> Key {
    const Symbol symbol(key);
    if (symbol.tag() == 'x') return symbol.index();
    return symbol.index() == 3 ? 3 : 4;
  };
  const PoseGraphFile back = readPoseGraph(path, GraphFormat::G2o);
  ASSERT_EQ(back.initial.size(), 5u);
  for (const auto& [key, value] : file.initial) expectSameValue(back.initial.value(idOf(key)), value);
  expectSameEdges(file.factors, back.factors, idOf);
}

TEST(G2oWriter, IsamCityTreesRoundTrip) {
  SEMSLAM_REQUIRE_DATA(source, "isam/cityTrees10000.txt");
  TempDir dir;
  const PoseGraphFile file = readPoseGraph(source.string(), GraphFormat::Isam);
  const std::string path = dir.path("cityTrees.g2o");
  writeG2o(path, file.factors, file.initial);
  const PoseGraphFile back = readPoseGraph(path, GraphFormat::G2o);
  EXPECT_EQ(back.initial.size(), 10100u);
  EXPECT_EQ(back.factors.size(), 14442u);
  const auto idOf = [](Key key) -> Key {
    const Symbol symbol(key);
    return symbol.tag() == 'x' ? symbol.index() : 10000 + symbol.index();  // landmarks 0..99 follow pose 9999
  };
  for (const auto& [key, value] : file.initial) expectSameValue(back.initial.value(idOf(key)), value);
  expectSameEdges(file.factors, back.factors, idOf);
}

TEST(G2oIds, Numbering) {
  EXPECT_EQ(g2oIds({5, 2, 9}), (std::map<Key, std::uint64_t>{{2, 2}, {5, 5}, {9, 9}}));
  const std::map<Key, std::uint64_t> ids =
      g2oIds({landmarkKey(0), poseKey(4), Symbol('o', 1), poseKey(2), landmarkKey(8), 1});
  EXPECT_EQ(ids.at(1), 1u);
  EXPECT_EQ(ids.at(poseKey(2)), 2u);
  EXPECT_EQ(ids.at(poseKey(4)), 4u);
  EXPECT_EQ(ids.at(landmarkKey(0)), 5u);  // 'l' < 'o' in key order
  EXPECT_EQ(ids.at(landmarkKey(8)), 6u);
  EXPECT_EQ(ids.at(Symbol('o', 1)), 7u);
  EXPECT_EQ(g2oIds({landmarkKey(3)}).at(landmarkKey(3)), 0u);
  EXPECT_THROW(g2oIds({3, poseKey(3)}), std::invalid_argument);
}

TEST(G2oWriter, FailureLeavesNoFile) {
  TempDir dir;
  const std::string path = dir.path("out.g2o");
  Values values;
  values.insert(0, SE2());
  values.insert(1, SO2(0.3));  // no g2o vertex record
  EXPECT_THROW(writeG2o(path, FactorGraph(), values), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));

  // An existing file is left untouched by a failed write.
  const std::string existing = dir.write("keep.g2o", "VERTEX_SE2 0 0 0 0\n");
  FactorGraph dangling;
  dangling.emplace<BetweenFactor<SE2>>(0, 5, SE2(), NoiseModel::isotropic(3, 1.0));
  Values one;
  one.insert(0, SE2());
  EXPECT_THROW(writeG2o(existing, dangling, one), std::invalid_argument);
  EXPECT_EQ(readText(existing), "VERTEX_SE2 0 0 0 0\n");
  EXPECT_FALSE(std::filesystem::exists(existing + ".tmp"));

  EXPECT_THROW(writeG2o(path, FactorGraph(), one, {3}), std::invalid_argument);  // fixed key without a value
  EXPECT_THROW(writeG2o(dir.path("no/such/dir.g2o"), FactorGraph(), one), std::runtime_error);
}

}  // namespace
}  // namespace semslam
