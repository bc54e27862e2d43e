#include "semslam/io/PoseGraphFile.h"

#include <cmath>
#include <stdexcept>

#include "semslam/core/ExactNumber.h"
#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/G2oIds.h"
#include "semslam/core/InputError.h"
#include "semslam/io/PoseGraphReaders.h"
#include "semslam/io/TriangularEntries.h"

namespace semslam {

GraphFormat parseGraphFormat(const std::string& name) {
  if (name == "g2o") return GraphFormat::G2o;
  if (name == "toro") return GraphFormat::Toro;
  if (name == "isam") return GraphFormat::Isam;
  throw InputError("unknown pose-graph format '" + name + "' (expected g2o, toro or isam)");
}

PoseGraphFile readPoseGraph(const std::string& path, GraphFormat format) {
  switch (format) {
    case GraphFormat::G2o:
      return readG2oFile(path);
    case GraphFormat::Toro:
      return readToroFile(path);
    case GraphFormat::Isam:
      return readIsamFile(path);
  }
  throw std::invalid_argument("readPoseGraph: invalid GraphFormat");
}

namespace {

/// One g2o record, built field by field; numbers are written in the shortest form that reads back exactly.
class Record {
 public:
  explicit Record(const char* tag) : text_(tag) {}

  Record& id(std::uint64_t id) {
    text_ += ' ';
    text_ += std::to_string(id);
    return *this;
  }

  Record& number(double value) {
    if (!std::isfinite(value)) {
      throw std::invalid_argument("writeG2o: non-finite number in record '" + text_ + " ...'");
    }
    text_ += ' ';
    text_ += shortestExactNumber(value);
    return *this;
  }

  template <class Vec>
  Record& numbers(const Vec& values) {
    for (double value : values) number(value);
    return *this;
  }

  Record& quaternion(const SO3& rotation) {
    const Eigen::Quaterniond q = rotation.toQuaternion();
    return number(q.x()).number(q.y()).number(q.z()).number(q.w());
  }

  Record& information(const SharedNoiseModel& noise) { return numbers(upperEntries(noise->information())); }

  void writeTo(std::ostream& out) {
    text_ += '\n';
    out.write(text_.data(), static_cast<std::streamsize>(text_.size()));
  }

 private:
  std::string text_;
};

class G2oWriter {
 public:
  G2oWriter(const Values& values, const std::map<Key, std::uint64_t>& ids) : values_(values), ids_(ids) {}

  void vertex(Key key, const Value& value, std::ostream& out) const {
    const std::uint64_t id = ids_.at(key);
    if (const SE2* pose = std::get_if<SE2>(&value)) {
      Record("VERTEX_SE2").id(id).number(pose->x()).number(pose->y()).number(pose->theta()).writeTo(out);
    } else if (const Point2* point = std::get_if<Point2>(&value)) {
      Record("VERTEX_XY").id(id).numbers(*point).writeTo(out);
    } else if (const SE3* pose3 = std::get_if<SE3>(&value)) {
      Record("VERTEX_SE3:QUAT").id(id).numbers(pose3->translation()).quaternion(pose3->rotation()).writeTo(out);
    } else {
      throw std::invalid_argument("writeG2o: variable " + keyToString(key) + " is a " + typeName(value) +
                                  ", which has no g2o vertex record (SE2, Point2 and SE3 do)");
    }
  }

  /// Writes `factor` if it is one of the g2o edge types; other factors are skipped.
  void edge(const Factor& factor, std::ostream& out) const {
    if (const auto* between = dynamic_cast<const BetweenFactor<SE2>*>(&factor)) {
      const SE2& z = between->measured();
      Record("EDGE_SE2")
          .id(idOf(factor, 0))
          .id(idOf(factor, 1))
          .number(z.x())
          .number(z.y())
          .number(z.theta())
          .information(between->noiseModel())
          .writeTo(out);
    } else if (const auto* point = dynamic_cast<const RelativePointFactor<SE2, Point2>*>(&factor)) {
      Record("EDGE_SE2_XY")
          .id(idOf(factor, 0))
          .id(idOf(factor, 1))
          .numbers(point->measured())
          .information(point->noiseModel())
          .writeTo(out);
    } else if (const auto* between3 = dynamic_cast<const BetweenFactor<SE3>*>(&factor)) {
      const SE3& z = between3->measured();
      Record("EDGE_SE3:QUAT")
          .id(idOf(factor, 0))
          .id(idOf(factor, 1))
          .numbers(z.translation())
          .quaternion(z.rotation())
          .information(between3->noiseModel())
          .writeTo(out);
    }
  }

 private:
  std::uint64_t idOf(const Factor& factor, std::size_t k) const {
    const Key key = factor.keys()[k];
    if (!values_.exists(key)) {
      throw std::invalid_argument("writeG2o: an edge names " + keyToString(key) + ", which has no value");
    }
    return ids_.at(key);
  }

  const Values& values_;
  const std::map<Key, std::uint64_t>& ids_;
};

}  // namespace

void writeG2o(const std::string& path, const FactorGraph& graph, const Values& values, const std::vector<Key>& fixed) {
  for (Key key : fixed) {
    if (!values.exists(key)) throw std::invalid_argument("writeG2o: fixed " + keyToString(key) + " has no value");
  }
  const std::map<Key, std::uint64_t> ids = g2oIds(values.keys());
  std::map<std::uint64_t, Key> byId;
  for (const auto& [key, id] : ids) byId.emplace(id, key);
  const G2oWriter writer(values, ids);
  writeFileAtomically(path, [&](std::ostream& out) {
    for (const auto& [id, key] : byId) writer.vertex(key, values.value(key), out);
    for (Key key : fixed) Record("FIX").id(ids.at(key)).writeTo(out);
    for (const FactorPtr& factor : graph) writer.edge(*factor, out);
  });
}

}  // namespace semslam
