#pragma once
// The measurement log file: JSON lines, one header object on the first line, then one object per time step.
// Full specification, with an example: docs/measurement-log.md. The in-memory form is models/MeasurementLog.h.
//
//   {"format":"semslam-log","version":1,"dimension":2,"classes":3,"semantic":"label",
//    "classifier":{"kind":"categorical","misclassification":0.1},
//    "sensor":{"kind":"range-bearing","body_to_sensor":[0.0,0.0,0.0],"max_range":10.0,"field_of_view":0.0},
//    "landmarks_have_pose":false, ["initial_pose":{...}], ["landmark_priors":[...]], ["landmark_truth":[...]],
//    ["source":"..."]}
//   {"time":0.0,"detections":[{"geometry":[2.5,0.3],"covariance":[[0.01,0.0],[0.0,0.001]],"label":1,"truth":4}]}
//   {"time":0.1,"odometry":{"increment":[0.1,0.0,0.01],"covariance":[[...],[...],[...]]},"detections":[],
//    "true_pose":[0.1,0.0,0.01]}
//
// Reading validates every record and throws InputError(file, line, problem) at the first problem: the line is the
// JSONL line number (1 = the header; 0 = the file as a whole: missing, empty, no steps). Checked: valid JSON, an
// object, no unknown or duplicate keys, every required key, types (integers where integers are meant), finite
// numbers, lengths (poses per dimension, geometry per sensor kind, class vectors per class count), covariances
// square, symmetric, positive definite, unit quaternions, enum names, labels and ids in range, probabilities on the
// simplex, the semantic field present exactly when the header says so, time strictly increasing, odometry on
// every step but the first, and detection truth ids among the header's landmark truth where that is given.
//
// Writing produces deterministic bytes (fixed key order; every double printed in the shortest form that reads back
// to the same double) and writes atomically: the file is complete or untouched. The writer validates every record
// with the reader's own rules first and throws std::invalid_argument naming the record and the problem, so every
// log it writes reads back. Reading a file the writer wrote and writing it again gives the same bytes.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

inline constexpr std::string_view kMeasurementLogFormat = "semslam-log";
/// The version this code writes, and the newest it reads. Version 2 added the detection truth "unknown"
/// (kUnknownTruth) (docs/measurement-log.md, "Versioning").
inline constexpr int kMeasurementLogVersion = 2;
/// The first version whose detections may have "truth": "unknown".
inline constexpr int kUnknownTruthVersion = 2;
/// The most classes a log may declare: a categorical classifier allocates an M x M confusion matrix from the
/// header alone, 32 MiB at 2048 (docs/measurement-log.md, "Limits"). Converters refuse a larger --classes first.
inline constexpr int kMaxLogClasses = 2048;

/// Reads and validates a whole log. Throws InputError(path, line, problem).
MeasurementLog readMeasurementLog(const std::string& path);

/// Writes `log` (version kMeasurementLogVersion, whatever log.header.version holds) to `path`, atomically.
/// Throws std::invalid_argument for a log the reader would reject ("step 12: detections[0].covariance: not
/// positive definite"), std::runtime_error when the file cannot be written.
void writeMeasurementLog(const std::string& path, const MeasurementLog& log);

/// Reads a log one time step at a time, validating as readMeasurementLog does, for logs too long to hold.
class MeasurementLogReader {
 public:
  /// Opens `path` and reads and validates its header. Throws InputError.
  explicit MeasurementLogReader(const std::string& path);
  ~MeasurementLogReader();
  MeasurementLogReader(MeasurementLogReader&&) noexcept;
  MeasurementLogReader& operator=(MeasurementLogReader&&) noexcept;

  const std::string& path() const;
  const LogHeader& header() const;
  /// Reads the next time step into `step`; false at the end of the file. Throws InputError for a bad record,
  /// and at the end for a log with no time steps.
  bool next(TimeStep& step);
  /// The line of the last record read (1 after the constructor).
  std::size_t lineNumber() const;
  std::size_t stepsRead() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// The names the file uses: "range-bearing", "range-bearing-elevation", "relative-position", "relative-pose".
std::string_view sensorKindName(SensorKind kind);
/// "none", "label", "probabilities", "scores".
std::string_view semanticKindName(SemanticKind kind);
/// "none", "categorical", "viewpoint-gaussian".
std::string_view classifierKindName(ClassifierModelSpec::Kind kind);

}  // namespace semslam
