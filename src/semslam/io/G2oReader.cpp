// g2o pose graphs: VERTEX_SE2, VERTEX_XY, VERTEX_SE3:QUAT, EDGE_SE2, EDGE_SE2_XY, EDGE_SE3:QUAT and FIX records
// (see PoseGraphFile.h and docs/file-formats.md). Ids are plain keys; vertices come before the records naming them.

#include <array>
#include <string_view>
#include <vector>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/io/PoseGraphBuilder.h"
#include "semslam/io/PoseGraphReaders.h"
#include "semslam/io/TriangularEntries.h"
#include "semslam/io/UnreadRecord.h"

namespace semslam {

namespace {

constexpr std::array<std::string_view, 4> kVertexSE2 = {"id", "x", "y", "theta"};
constexpr std::array<std::string_view, 3> kVertexXY = {"id", "x", "y"};
constexpr std::array<std::string_view, 8> kVertexSE3 = {"id", "x", "y", "z", "qx", "qy", "qz", "qw"};
constexpr std::array<std::string_view, 11> kEdgeSE2 = {"i",   "j",   "dx",  "dy",  "dtheta", "I11",
                                                       "I12", "I13", "I22", "I23", "I33"};
constexpr std::array<std::string_view, 7> kEdgeSE2XY = {"i", "l", "dx", "dy", "I11", "I12", "I22"};
constexpr std::array<std::string_view, 30> kEdgeSE3 = {
    "i",   "j",   "x",   "y",   "z",   "qx",  "qy",  "qz",  "qw",  "I11", "I12", "I13", "I14", "I15", "I16",
    "I22", "I23", "I24", "I25", "I26", "I33", "I34", "I35", "I36", "I44", "I45", "I46", "I55", "I56", "I66"};

constexpr const char* kSupported = "VERTEX_SE2 VERTEX_XY VERTEX_SE3:QUAT EDGE_SE2 EDGE_SE2_XY EDGE_SE3:QUAT FIX";

bool startsWith(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

/// Values first..first+3 as a quaternion (qx qy qz qw), normalised; a zero one is an error.
SO3 readQuaternion(const LineReader& reader, std::size_t first) {
  const std::vector<double> q = reader.numbers(first, 4);
  const Eigen::Quaterniond quaternion(q[3], q[0], q[1], q[2]);
  const double norm = quaternion.coeffs().stableNorm();  // no overflow for huge entries
  if (!(norm >= 1e-12)) {
    reader.fail(std::string(reader.tag()) + ": quaternion (qx qy qz qw) is zero (norm below 1e-12) and cannot be " +
                "normalised");
  }
  return SO3::fromQuaternion(Eigen::Quaterniond(quaternion.coeffs() / norm));
}

[[noreturn]] void unknownRecord(const LineReader& reader) {
  const std::string_view tag = reader.tag();
  if (startsWith(tag, "VERTEX_") || startsWith(tag, "EDGE_") || startsWith(tag, "PARAMS_") ||
      startsWith(tag, "CACHE_")) {
    reader.fail("unsupported g2o record type '" + std::string(tag) + "' (g2o records read here: " + kSupported + ")");
  }
  const auto isToroOrIsamRecord = [](std::string_view t) {
    return t == "VERTEX2" || t == "EDGE2" || t == "VERTEX" || t == "EDGE" || t == "EQUIV" || t == "ODOMETRY" ||
           t == "LANDMARK";
  };
  failUnreadRecord(reader, "g2o", kSupported, {{"TORO or iSAM", "toro or isam", isToroOrIsamRecord}});
}

}  // namespace

PoseGraphFile readG2oFile(const std::string& path) {
  LineReader reader(path);
  PoseGraphBuilder graph(reader);
  while (reader.next()) {
    // Each record is parsed field by field, left to right, before its vertices are looked up, so the first
    // malformed field is the one reported.
    const std::string_view tag = reader.tag();
    if (tag == "VERTEX_SE2") {
      reader.requireValueCount(kVertexSE2);
      const Key id = reader.id(1);
      const std::vector<double> v = reader.numbers(2, 3);
      graph.requireDimension(2);
      graph.addVertex(id, SE2(v[0], v[1], v[2]));
    } else if (tag == "VERTEX_XY") {
      reader.requireValueCount(kVertexXY);
      const Key id = reader.id(1);
      const std::vector<double> v = reader.numbers(2, 2);
      graph.requireDimension(2);
      graph.addVertex(id, Point2(v[0], v[1]));
    } else if (tag == "VERTEX_SE3:QUAT") {
      reader.requireValueCount(kVertexSE3);
      const Key id = reader.id(1);
      const std::vector<double> t = reader.numbers(2, 3);
      const SO3 rotation = readQuaternion(reader, 5);
      graph.requireDimension(3);
      graph.addVertex(id, SE3(rotation, Point3(t[0], t[1], t[2])));
    } else if (tag == "EDGE_SE2") {
      reader.requireValueCount(kEdgeSE2);
      const Key i = reader.id(1), j = reader.id(2);
      const std::vector<double> z = reader.numbers(3, 3);
      const std::vector<double> information = reader.numbers(6, 6);
      graph.requireDimension(2);
      graph.vertex<SE2>(1, i);
      graph.vertex<SE2>(2, j);
      graph.requireDistinct(i, j);
      const SharedNoiseModel noise = graph.fromInformation(symmetricFromUpper(information, 3));
      graph.addFactor(std::make_shared<const BetweenFactor<SE2>>(i, j, SE2(z[0], z[1], z[2]), noise));
    } else if (tag == "EDGE_SE2_XY") {
      reader.requireValueCount(kEdgeSE2XY);
      const Key i = reader.id(1), l = reader.id(2);
      const std::vector<double> z = reader.numbers(3, 2);
      const std::vector<double> information = reader.numbers(5, 3);
      graph.requireDimension(2);
      graph.vertex<SE2>(1, i);
      graph.vertex<Point2>(2, l);
      const SharedNoiseModel noise = graph.fromInformation(symmetricFromUpper(information, 2));
      graph.addFactor(std::make_shared<const RelativePointFactor<SE2, Point2>>(i, l, Point2(z[0], z[1]), noise));
    } else if (tag == "EDGE_SE3:QUAT") {
      reader.requireValueCount(kEdgeSE3);
      const Key i = reader.id(1), j = reader.id(2);
      const std::vector<double> t = reader.numbers(3, 3);
      const SO3 rotation = readQuaternion(reader, 6);
      const std::vector<double> information = reader.numbers(10, 21);
      graph.requireDimension(3);
      graph.vertex<SE3>(1, i);
      graph.vertex<SE3>(2, j);
      graph.requireDistinct(i, j);
      const SharedNoiseModel noise = graph.fromInformation(symmetricFromUpper(information, 6));
      const SE3 measured(rotation, Point3(t[0], t[1], t[2]));
      graph.addFactor(std::make_shared<const BetweenFactor<SE3>>(i, j, measured, noise));
    } else if (tag == "FIX") {
      reader.requireAtLeast(1, "id");
      for (std::size_t k = 1; k <= reader.valueCount(); ++k) graph.addFixed(k, reader.id(k));
    } else {
      unknownRecord(reader);
    }
  }
  return graph.finish();
}

}  // namespace semslam
