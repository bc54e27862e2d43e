#include "semslam/study/StudyRowBytes.h"

#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace semslam {
namespace {

class ByteWriter {
 public:
  template <typename T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void text(const std::string& s) {
    value<std::uint64_t>(s.size());
    bytes_ += s;
  }
  template <typename T>
  void optional(const std::optional<T>& v) {
    value<std::uint8_t>(v ? 1 : 0);
    if (v) value(*v);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  std::string text() {
    const auto size = value<std::uint64_t>();
    return std::string(take(size), size);
  }
  template <typename T>
  std::optional<T> optional() {
    if (value<std::uint8_t>() == 0) return std::nullopt;
    return value<T>();
  }
  bool atEnd() const { return position_ == bytes_.size(); }

 private:
  const char* take(std::size_t size) {
    if (size > bytes_.size() - position_) throw std::runtime_error("study row bytes: truncated record");
    const char* start = bytes_.data() + position_;
    position_ += size;
    return start;
  }
  const std::string& bytes_;
  std::size_t position_ = 0;
};

void writeRobustnessRow(ByteWriter& out, const RobustnessRow& row) {
  out.value(static_cast<std::int32_t>(row.axis));
  out.value(row.level);
  out.value(row.seed);
  out.text(row.method);
  out.value(row.ateRmse);
  out.value(row.rotRmse);
  out.value(row.daAccuracy);
  out.value(row.daAccuracyReal);
  out.optional(row.landmarksEstimated);
  out.optional(row.landmarksTrue);
  out.value(row.timeSeconds);
  out.optional(row.stuck);
  out.text(row.error);
}

RobustnessRow readRobustnessRow(ByteReader& in) {
  RobustnessRow row;
  row.axis = static_cast<RobustnessAxis>(in.value<std::int32_t>());
  row.level = in.value<double>();
  row.seed = in.value<int>();
  row.method = in.text();
  row.ateRmse = in.value<double>();
  row.rotRmse = in.value<double>();
  row.daAccuracy = in.value<double>();
  row.daAccuracyReal = in.value<double>();
  row.landmarksEstimated = in.optional<long long>();
  row.landmarksTrue = in.optional<long long>();
  row.timeSeconds = in.value<double>();
  row.stuck = in.optional<bool>();
  row.error = in.text();
  return row;
}

void expectEnd(const ByteReader& in) {
  if (!in.atEnd()) throw std::runtime_error("study row bytes: trailing bytes after the record");
}

}  // namespace

std::string encodeHybridStudyRow(const HybridStudyRow& row) {
  ByteWriter out;
  out.value(row.layout);
  out.value(row.alpha);
  out.text(row.model);
  out.value(row.track);
  for (double v : {row.entropy, row.detCov, row.errWmax, row.errWavg, row.ess}) out.value(v);
  out.value(row.components);
  out.value(row.finalNees);
  out.value(row.heaviestComponentCorrect);
  out.value(row.mixtureNees);
  out.value(row.assocWeightAtStep);
  out.value(row.disambiguatedAtStep);
  out.value(row.heaviestHistoryCorrect);
  out.value(row.gateLostMass);
  out.value(row.analyticTotalVariation);
  out.value(row.sampledCandidates);
  out.value(row.samplingSeconds);
  out.value(row.seconds);
  out.text(row.error);
  return out.bytes();
}

HybridStudyRow decodeHybridStudyRow(const std::string& bytes) {
  ByteReader in(bytes);
  HybridStudyRow row;
  row.layout = in.value<int>();
  row.alpha = in.value<double>();
  row.model = in.text();
  row.track = in.value<int>();
  for (double* v : {&row.entropy, &row.detCov, &row.errWmax, &row.errWavg, &row.ess}) *v = in.value<double>();
  row.components = in.value<int>();
  row.finalNees = in.value<double>();
  row.heaviestComponentCorrect = in.value<bool>();
  row.mixtureNees = in.value<double>();
  row.assocWeightAtStep = in.value<double>();
  row.disambiguatedAtStep = in.value<bool>();
  row.heaviestHistoryCorrect = in.value<bool>();
  row.gateLostMass = in.value<double>();
  row.analyticTotalVariation = in.value<double>();
  row.sampledCandidates = in.value<long long>();
  row.samplingSeconds = in.value<double>();
  row.seconds = in.value<double>();
  row.error = in.text();
  expectEnd(in);
  return row;
}

std::string encodeRobustnessRows(const std::vector<RobustnessRow>& rows) {
  ByteWriter out;
  out.value<std::uint64_t>(rows.size());
  for (const RobustnessRow& row : rows) writeRobustnessRow(out, row);
  return out.bytes();
}

std::vector<RobustnessRow> decodeRobustnessRows(const std::string& bytes) {
  ByteReader in(bytes);
  std::vector<RobustnessRow> rows(in.value<std::uint64_t>());
  for (RobustnessRow& row : rows) row = readRobustnessRow(in);
  expectEnd(in);
  return rows;
}

}  // namespace semslam
