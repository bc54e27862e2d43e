#pragma once
// RunMetrics: everything one run of one method is scored by, and its file, metrics.json. Every method (paper A's
// hybrid belief, paper B's five strategies, any later one) writes the same schema, so runs can be compared and
// aggregated by one script. docs/metrics.md documents every field: definition, units, conventions.
//
// In memory, a field that does not apply to a run (hybrid-belief metrics for paper B's methods, data association
// accuracy without detection ground truth, NEES without covariances) is NaN (numbers), std::nullopt (counts) or
// an empty `alignment`; in the file it is `null`. Non-finite numbers are written as `null` too (JSON has no NaN).
// `method` is always a string (possibly empty).
//
// File: one JSON object, keys in the fixed order of runMetricsKeys() (the order of docs/metrics.md), two-space
// indentation, numbers in shortest round-trip form (reading gives back the same doubles bit for bit). Written
// atomically (io/AtomicFile.h). Reading requires "schema": "semslam.metrics/1", accepts a missing known key as
// null and ignores unknown keys; a known key of the wrong type throws InputError(file, 0, problem).

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace semslam {

inline constexpr std::string_view kRunMetricsSchema = "semslam.metrics/1";

struct RunMetrics {
  static constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

  std::string method;                  ///< "method": e.g. "hybrid", "mm+nh"
  std::optional<long long> dimension;  ///< "dimension": 2 or 3
  double timeSeconds = kNotApplicable; ///< "time_s": wall-clock time of the estimation (s)

  // Trajectory (TrajectoryMetrics.h): positions after rigid alignment; rotations in radians.
  std::string alignment;               ///< "alignment": "se2" | "se3" | "none"
  std::optional<long long> poses;      ///< "poses": poses compared
  double ateRmse = kNotApplicable, ateMean = kNotApplicable, ateMedian = kNotApplicable, ateMax = kNotApplicable;
  double rotRmse = kNotApplicable, rotMean = kNotApplicable, rotMedian = kNotApplicable, rotMax = kNotApplicable;

  // Data association (DataAssociationAccuracy.h).
  double daAccuracy = kNotApplicable;
  std::optional<long long> daCorrect, daTotal, daNull, daClutter;

  // Landmarks (LandmarkMetrics.h).
  std::optional<long long> landmarksEstimated, landmarksTrue, landmarkCountError, landmarksMatched;
  double landmarkRmse = kNotApplicable;
  double classAccuracy = kNotApplicable;

  // Consistency (Nees.h).
  double neesMean = kNotApplicable;
  std::optional<long long> neesCount, neesDof;
  double neesLower = kNotApplicable, neesUpper = kNotApplicable;

  // Hybrid belief (HypothesisMetrics.h), at the final time step.
  double entropy = kNotApplicable;
  double detCov = kNotApplicable;
  double errWmax = kNotApplicable;
  double errWavg = kNotApplicable;
  double ess = kNotApplicable;
  double assocWeightMax = kNotApplicable;
  double disambiguatedFraction = kNotApplicable;
  std::optional<long long> components, histories;
};

/// The keys of metrics.json, in file order ("schema" first).
const std::vector<std::string>& runMetricsKeys();

/// The metrics.json text (ends with a newline).
std::string runMetricsToJson(const RunMetrics& metrics);
/// Parses metrics.json text; `source` names it in errors (a file name, or "<string>").
RunMetrics runMetricsFromJson(const std::string& text, const std::string& source = "<string>");

/// Writes metrics.json atomically; throws std::runtime_error when the file cannot be written.
void writeRunMetrics(const std::string& path, const RunMetrics& metrics);
/// Reads metrics.json; throws InputError for an unreadable or malformed file.
RunMetrics readRunMetrics(const std::string& path);

}  // namespace semslam
