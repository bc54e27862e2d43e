#pragma once
// MeasurementLogSummary: what `semslam check LOG` says about a measurement log (docs/measurement-log.md). The log
// is read as a stream (MeasurementLogReader), so reading it validates it (InputError with file and line on the
// first problem) without holding it in memory; the summary counts its steps, detections, ground truth and
// priors, and, on request, the residuals of its detections and odometry against its own ground truth
// (eval/MeasurementResiduals.h). formatMeasurementLogSummary is the text `semslam check` prints.

#include <cstddef>
#include <limits>
#include <optional>
#include <string>

#include "semslam/eval/MeasurementResiduals.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

struct MeasurementLogSummary {
  std::string path;
  LogHeader header;
  std::size_t steps = 0;
  std::size_t detections = 0;
  std::size_t minPerStep = std::numeric_limits<std::size_t>::max();
  std::size_t maxPerStep = 0;
  std::size_t withTruth = 0;  ///< detections with a truth id (a landmark's, or clutter)
  std::size_t clutter = 0;
  std::size_t unknownTruth = 0;  ///< of withTruth: truth "unknown" (neither a landmark nor clutter)
  std::size_t truePoses = 0;
  std::size_t withOdometry = 0;
  double firstTime = 0.0;
  double lastTime = 0.0;
  std::optional<LogResidualStatistics> residuals;  ///< when asked for
};

/// Reads and validates the log at `path`; throws InputError on the first problem.
MeasurementLogSummary summarizeMeasurementLog(const std::string& path, bool residuals);

/// The summary as `semslam check` prints it: "PATH: valid ..., version N", then dimension, sensor, classes,
/// steps, duration, detections, ground truth, priors, source, and the residual table when present.
std::string formatMeasurementLogSummary(const MeasurementLogSummary& summary);

}  // namespace semslam
