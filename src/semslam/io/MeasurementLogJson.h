#pragma once
// The measurement log's records as JSON, both ways: the schema of docs/measurement-log.md in code.
//
// Internal to the io layer (it includes nlohmann/json): MeasurementLogFile.cpp reads and writes lines with it.
// `headerFromJson` and `StepParser::parse` validate every rule of the specification that concerns one record (and,
// for a step, its place in the sequence: time order, odometry on every step but the first, truth ids), throwing
// InputError(file, line, "<path>: <problem>"). `headerToJson` and `stepToJson` write the records in the fixed key
// order of the specification; they do not validate (the writer runs the parsers over their output).

#include <optional>
#include <set>

#include "semslam/io/JsonField.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam::jsonio {

LogHeader headerFromJson(const JsonField& record);

/// Parses the steps of one log in order, keeping what the rules across steps need.
class StepParser {
 public:
  explicit StepParser(const LogHeader& header);
  TimeStep parse(const JsonField& record);
  std::size_t stepsParsed() const { return steps_; }

 private:
  Detection parseDetection(const JsonField& field) const;

  const LogHeader& header_;
  std::set<int> truthIds_;  // the header's landmark truth ids (empty: any id goes)
  std::size_t steps_ = 0;
  std::optional<double> previousTime_;
};

Json headerToJson(const LogHeader& header);
/// `semantic` names a detection's class vector ("probabilities" or "scores").
Json stepToJson(const TimeStep& step, SemanticKind semantic);

}  // namespace semslam::jsonio
