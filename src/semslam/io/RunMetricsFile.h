#pragma once
// metrics.json: the file of one run's RunMetrics (eval/RunMetrics.h), the same schema for every method.
//
// File: one JSON object, keys in the fixed order of runMetricsKeys() (the order of docs/metrics.md), two-space
// indentation, numbers in shortest round-trip form (reading gives back the same doubles bit for bit). Written
// atomically (io/AtomicFile.h). "version" (second) is the semslam release that wrote the file (core/Version.h); it
// is not part of RunMetrics and reading skips it. Reading requires "schema": "semslam.metrics/1", accepts a missing
// known key as null and ignores unknown keys; a known key of the wrong type throws InputError(file, 0, problem).

#include <string>
#include <string_view>
#include <vector>

#include "semslam/eval/RunMetrics.h"

namespace semslam {

inline constexpr std::string_view kRunMetricsSchema = "semslam.metrics/1";

/// The keys of metrics.json, in file order ("schema", then "version", first).
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
