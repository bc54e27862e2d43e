#pragma once
// Pieces every dataset converter shares: reading the datasets' numeric text tables, finding the step of a time
// stamp, and the common tail of every conversion (keyframing, truncation, labels, priors, source text).

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "semslam/io/NumericTable.h"
#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/io/convert/SourceLines.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// `folder`/`name`; throws InputError(folder, 0, ...) when `folder` is not a directory.
std::string datasetFile(const std::string& folder, const std::string& name);

/// The data rows of a whitespace-separated table ('#' comments) with exactly `columns` numbers each; throws
/// InputError(path, line, ...) naming `columns` ("t v omega") for a row of another length, and for a file without
/// rows.
std::vector<NumericRow> readDatasetTable(const std::string& path, std::size_t columns, const std::string& names);

/// A dataset's integer field (an id, an index, a flag): throws InputError(path, line, ...) unless `value` is an
/// integer in [minimum, maximum].
int integerField(const std::string& path, const NumericRow& row, std::size_t column, const std::string& name,
                 int minimum, int maximum);

/// Reads a landmark ground-truth table — an integer id (named `idName` in messages), then `dimension` coordinates,
/// then any further columns (`columns` in all, named by `names`) — appending one LandmarkTruth per row to `truth`.
/// Appends each row's line to `rows` (LogSources::landmarks) alongside. Returns the ids; an id that appears twice is
/// an InputError naming the file and line.
std::set<int> readLandmarkTruthTable(const std::string& path, int dimension, std::size_t columns,
                                    const std::string& names, const std::string& idName,
                                    std::vector<LandmarkTruth>& truth, std::vector<SourceLine>& rows);

/// The index of the step whose time is within `tolerance` of `time` (steps sorted by time), if any.
std::optional<std::size_t> findStep(const std::vector<TimeStep>& steps, double time, double tolerance);

/// diag(values) as a covariance.
Matrix diagonalCovariance(const std::vector<double>& values);

/// The common tail of a conversion: validates `options`, keyframes, truncates, assigns labels and classes (unless
/// `raw`'s header already has a semantic kind: then the dataset's own labels stay, and --classes or
/// --misclassification is an InputError), sets
/// the initial pose prior (at the first step's true pose, or the identity when it has none) and the map prior, and
/// appends the settings and counts to the header's source text, then checks the log with the reader's rules
/// (checkConvertedLog: an InputError at the dataset row that made the refused part). `raw` holds every step and
/// detection of the dataset, its header the dimension, sensor, landmark truth and a description of the dataset in
/// `source`; `sources` the rows that made them, parallel to `raw` (std::invalid_argument otherwise).
MeasurementLog finishConversion(MeasurementLog raw, LogSources sources, const ConvertOptions& options,
                                ConversionStats* stats);

}  // namespace semslam
