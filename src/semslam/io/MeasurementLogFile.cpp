#include "semslam/io/MeasurementLogFile.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "semslam/core/InputError.h"
#include "semslam/core/InputFile.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/MeasurementLogJson.h"
#include "semslam/io/StrictJson.h"

namespace semslam {

using jsonio::Json;
using jsonio::JsonField;
using jsonio::JsonLocation;

namespace {

bool isBlankLine(const std::string& line) {
  return std::all_of(line.begin(), line.end(), [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
}

}  // namespace

// ---- reading ----

struct MeasurementLogReader::State {
  std::ifstream stream;
  JsonLocation location;  // file, and the line of the last record read
  std::size_t physicalLine = 0;
  std::string line;
  LogHeader header;
  std::optional<jsonio::StepParser> steps;

  /// Reads the next non-blank line into `record`; false at the end of the file.
  bool nextRecord(Json& record) {
    while (readBoundedLine(stream, line, location.file, physicalLine + 1)) {
      ++physicalLine;
      if (isBlankLine(line)) continue;
      location.line = physicalLine;
      record = jsonio::parseStrictJson(line, location.file, location.line);
      return true;
    }
    return false;
  }
};

MeasurementLogReader::MeasurementLogReader(const std::string& path) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.location.file = path;
  s.stream = openInputFile(path);
  Json record;
  if (!s.nextRecord(record)) {
    throw InputError(path, 0, "the file is empty: expected a header line, then one line per time step");
  }
  s.header = jsonio::headerFromJson(JsonField(record, s.location));
  s.steps.emplace(s.header);
}

MeasurementLogReader::~MeasurementLogReader() = default;
MeasurementLogReader::MeasurementLogReader(MeasurementLogReader&&) noexcept = default;
MeasurementLogReader& MeasurementLogReader::operator=(MeasurementLogReader&&) noexcept = default;

const std::string& MeasurementLogReader::path() const { return state_->location.file; }
const LogHeader& MeasurementLogReader::header() const { return state_->header; }
std::size_t MeasurementLogReader::lineNumber() const { return state_->location.line; }
std::size_t MeasurementLogReader::stepsRead() const { return state_->steps->stepsParsed(); }

bool MeasurementLogReader::next(TimeStep& step) {
  State& s = *state_;
  Json record;
  if (!s.nextRecord(record)) {
    if (s.steps->stepsParsed() == 0) {
      throw InputError(s.location.file, 0, "no time steps: the file has a header but no step lines after it");
    }
    return false;
  }
  step = s.steps->parse(JsonField(record, s.location));
  return true;
}

MeasurementLog readMeasurementLog(const std::string& path) {
  MeasurementLogReader reader(path);
  MeasurementLog log;
  log.header = reader.header();
  TimeStep step;
  while (reader.next(step)) log.steps.push_back(std::move(step));
  return log;
}

// ---- writing ----

namespace {

std::string dumpLine(const Json& record, const std::string& what) {
  try {
    return record.dump();
  } catch (const Json::exception& error) {
    // A string that is not valid UTF-8 (the header's source or table).
    throw std::invalid_argument(what + ": " + jsonio::jsonProblem(error.what()));
  }
}

}  // namespace

void writeMeasurementLog(const std::string& path, const MeasurementLog& log) {
  const std::string prefix = "cannot write measurement log " + path + ": ";
  if (log.steps.empty()) throw std::invalid_argument(prefix + "no time steps (a log has at least one)");
  // Every record is validated by the reader's own parsers before it is written, so the file reads back.
  JsonLocation location{path, 1};
  const Json header = jsonio::headerToJson(log.header);
  LogHeader validated;
  try {
    validated = jsonio::headerFromJson(JsonField(header, location));
  } catch (const InputError& error) {
    throw std::invalid_argument(prefix + "header: " + error.problem());
  }
  const std::string headerLine = dumpLine(header, prefix + "header");
  // A bad step throws inside the callback: the temporary file is removed and `path` is left untouched.
  writeFileAtomically(path, [&](std::ostream& out) {
    out << headerLine << '\n';
    jsonio::StepParser parser(validated);
    for (std::size_t k = 0; k < log.steps.size(); ++k) {
      location.line = k + 2;
      const std::string what = prefix + "step " + std::to_string(k);
      const Json step = jsonio::stepToJson(log.steps[k], log.header.semantic);
      try {
        parser.parse(JsonField(step, location));
      } catch (const InputError& error) {
        throw std::invalid_argument(what + ": " + error.problem());
      }
      out << dumpLine(step, what) << '\n';
    }
  });
}

}  // namespace semslam
