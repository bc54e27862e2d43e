#pragma once
// The last check of every conversion: the log a converter made, validated record by record with the measurement-log
// reader's own parsers (as writeMeasurementLog does before it writes), so that a dataset whose numbers a log may
// not hold (a speed of 1e308 integrated into a pose, a range below 1e-6, variances past 1e18 once composed by
// keyframing) is refused as an input error at the dataset row that caused it (io/convert/SourceLines.h), as the
// readers report their own errors, rather than by the writer afterwards (`semslam convert` exited 1) or by the log's
// step number.

#include "semslam/io/convert/SourceLines.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// Throws InputError(file, line, "the log made from it would be refused (log step 12): <field>: <problem>") at the
/// first record the reader would refuse; nothing when the reader accepts every record. The file and line are those
/// `sources` gives for the part that is refused on its own: a detection, the odometry, the true pose (also where
/// the header's initial pose prior is the first true pose), a landmark truth entry (with its map prior); else the
/// step's own row, or for the header the sensor's row. A part without a recorded row is reported at
/// `sources.dataset`, line 0. `sources` must be parallel to `log` (std::invalid_argument otherwise).
void checkConvertedLog(const MeasurementLog& log, const LogSources& sources);

}  // namespace semslam
