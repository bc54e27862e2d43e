// iSAM 2D files: EDGE2 / ODOMETRY and LANDMARK records with square-root information (see PoseGraphFile.h and
// docs/file-formats.md). Poses are x<i>, landmarks l<i>. There are no vertex records: the first odometry record's
// first pose is the identity, and every later pose is initialised by chaining the odometry record that first
// names it from its already known end (backwards, x_i = x_j · z⁻¹, when only the second pose is known);
// a landmark is initialised from its first observation, x_i ⊕ z.

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

constexpr std::array<std::string_view, 11> kOdometry = {"i",   "j",   "dx",  "dy",  "dtheta", "s11",
                                                        "s12", "s13", "s22", "s23", "s33"};
constexpr std::array<std::string_view, 7> kLandmark = {"i", "l", "dx", "dy", "s11", "s12", "s22"};

constexpr const char* kSupported = "EDGE2 ODOMETRY LANDMARK";

[[noreturn]] void unknownRecord(const LineReader& reader) {
  const std::string tag(reader.tag());
  if (tag == "EDGE3" || tag == "POINT3") {
    reader.fail("unsupported iSAM record type '" + tag + "' (3D; iSAM records read here: " + kSupported + ")");
  }
  const auto isToroRecord = [](std::string_view t) { return t == "VERTEX2" || t == "VERTEX" || t == "EQUIV"; };
  failUnreadRecord(reader, "iSAM", kSupported, {{"TORO", "toro", isToroRecord}, {"g2o", "g2o", isG2oRecordType}});
}

}  // namespace

PoseGraphFile readIsamFile(const std::string& path) {
  LineReader reader(path);
  PoseGraphBuilder graph(reader);
  graph.requireDimension(2);
  bool havePose = false;
  while (reader.next()) {
    const std::string_view tag = reader.tag();
    if (tag == "EDGE2" || tag == "ODOMETRY") {
      reader.requireValueCount(kOdometry);
      const Key i = poseKey(reader.id(1)), j = poseKey(reader.id(2));
      const std::vector<double> z = reader.numbers(3, 3);
      const std::vector<double> sqrtInformation = reader.numbers(6, 6);
      graph.requireDistinct(i, j);
      const SE2 measured(z[0], z[1], z[2]);
      const SharedNoiseModel noise = graph.fromSqrtInformation(upperFromEntries(sqrtInformation, 3));
      const bool knownI = graph.hasVertex(i), knownJ = graph.hasVertex(j);
      if (!knownI && !knownJ) {
        if (havePose) {
          reader.fail(std::string(tag) + " connects poses " + keyToString(i) + " and " + keyToString(j) +
                      ", neither of which appears in an earlier record, so neither can be initialised (iSAM poses " +
                      "are initialised by chaining odometry from the first pose)");
        }
        graph.addVertex(i, SE2());
        graph.addVertex(j, measured);
        havePose = true;
      } else if (!knownJ) {
        graph.addVertex(j, graph.vertex<SE2>(1, i) * measured);
      } else if (!knownI) {
        graph.addVertex(i, graph.vertex<SE2>(2, j) * measured.inverse());
      }
      graph.addFactor(std::make_shared<const BetweenFactor<SE2>>(i, j, measured, noise));
    } else if (tag == "LANDMARK") {
      reader.requireValueCount(kLandmark);
      const Key i = poseKey(reader.id(1)), l = landmarkKey(reader.id(2));
      const std::vector<double> z = reader.numbers(3, 2);
      const std::vector<double> sqrtInformation = reader.numbers(5, 3);
      const SharedNoiseModel noise = graph.fromSqrtInformation(upperFromEntries(sqrtInformation, 2));
      if (!graph.hasVertex(i)) {
        reader.fail(reader.describe(1) + " names pose " + keyToString(i) +
                    ", which does not appear in an earlier odometry record");
      }
      const Point2 measured(z[0], z[1]);
      if (!graph.hasVertex(l)) graph.addVertex(l, graph.vertex<SE2>(1, i).transformFrom(measured));
      graph.addFactor(std::make_shared<const RelativePointFactor<SE2, Point2>>(i, l, measured, noise));
    } else {
      unknownRecord(reader);
    }
  }
  return graph.finish();
}

}  // namespace semslam
