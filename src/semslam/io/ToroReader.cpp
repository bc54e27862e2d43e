// TORO 2D pose graphs: VERTEX2, EDGE2 and EQUIV records, and VERTEX / EDGE, the same records as TORO itself writes
// them (see PoseGraphFile.h and docs/file-formats.md).
//
// TORO orders an edge's information entries I_xx I_xy I_yy I_θθ I_xθ I_yθ (not g2o's row-major upper triangle):
//   Ω = [I_xx I_xy I_xθ; I_xy I_yy I_yθ; I_xθ I_yθ I_θθ].
// EQUIV i j asks TORO to collapse the edge between i and j (merge the two vertices through that edge, as if it were
// exact) in an optional step after loading. It adds no factor here; the pair is checked and returned in
// PoseGraphFile::equivalences.

#include <array>
#include <string_view>
#include <vector>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/io/PoseGraphBuilder.h"
#include "semslam/io/PoseGraphReaders.h"
#include "semslam/io/UnreadRecord.h"

namespace semslam {

namespace {

constexpr std::array<std::string_view, 4> kVertex2 = {"id", "x", "y", "theta"};
constexpr std::array<std::string_view, 11> kEdge2 = {"i",    "j",    "dx",   "dy",   "dtheta", "I_xx",
                                                     "I_xy", "I_yy", "I_tt", "I_xt", "I_yt"};
constexpr std::array<std::string_view, 2> kEquiv = {"i", "j"};

constexpr const char* kSupported = "VERTEX2 EDGE2 EQUIV, and VERTEX EDGE as TORO writes them";

/// TORO's six entries (I_xx I_xy I_yy I_θθ I_xθ I_yθ) as the information matrix over (x, y, θ).
Matrix toroInformation(const std::vector<double>& e) {
  Matrix3 information;
  information << e[0], e[1], e[4],  //
      e[1], e[2], e[5],             //
      e[4], e[5], e[3];
  return information;
}

[[noreturn]] void unknownRecord(const LineReader& reader) {
  const std::string tag(reader.tag());
  if (tag == "BR") {
    reader.fail("unsupported record type 'BR' (a bearing-range landmark measurement, an extension of TORO files " +
                std::string("that semslam does not read; TORO records read here: ") + kSupported + ")");
  }
  if (tag == "VERTEX3" || tag == "EDGE3") {
    reader.fail("unsupported record type '" + tag + "' (3D TORO; TORO records read here: " + kSupported + ")");
  }
  const auto isIsamRecord = [](std::string_view t) { return t == "ODOMETRY" || t == "LANDMARK"; };
  failUnreadRecord(reader, "TORO", kSupported, {{"iSAM", "isam", isIsamRecord}, {"g2o", "g2o", isG2oRecordType}});
}

}  // namespace

PoseGraphFile readToroFile(const std::string& path) {
  LineReader reader(path);
  PoseGraphBuilder graph(reader);
  graph.requireDimension(2);
  while (reader.next()) {
    const std::string_view tag = reader.tag();
    if (tag == "VERTEX2" || tag == "VERTEX") {
      reader.requireValueCount(kVertex2);
      const Key id = reader.id(1);
      const std::vector<double> v = reader.numbers(2, 3);
      graph.addVertex(id, SE2(v[0], v[1], v[2]));
    } else if (tag == "EDGE2" || tag == "EDGE") {
      reader.requireValueCount(kEdge2);
      const Key i = reader.id(1), j = reader.id(2);
      const std::vector<double> z = reader.numbers(3, 3);
      const std::vector<double> information = reader.numbers(6, 6);
      graph.vertex<SE2>(1, i);
      graph.vertex<SE2>(2, j);
      graph.requireDistinct(i, j);
      const SharedNoiseModel noise = graph.fromInformation(toroInformation(information));
      graph.addFactor(std::make_shared<const BetweenFactor<SE2>>(i, j, SE2(z[0], z[1], z[2]), noise));
    } else if (tag == "EQUIV") {
      reader.requireValueCount(kEquiv);
      const Key i = reader.id(1), j = reader.id(2);
      graph.addEquivalence(i, j);
    } else {
      unknownRecord(reader);
    }
  }
  return graph.finish();
}

}  // namespace semslam
