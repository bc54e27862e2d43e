#include "semslam/io/convert/ConversionCommon.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

#include "semslam/core/InputError.h"
#include "semslam/io/convert/ClassLabels.h"
#include "semslam/io/convert/ConvertedLogCheck.h"
#include "semslam/io/convert/Keyframing.h"

namespace semslam {

namespace {

/// The rows of the keyframes `chosen` (KeyframeSummary::chosen) of the steps `raw`: each keyframe keeps the rows of
/// its chosen step, its odometry the range of rows of every increment composed into it (when one file holds them).
std::vector<StepSources> keyframeSources(const std::vector<StepSources>& raw, const std::vector<std::size_t>& chosen) {
  std::vector<StepSources> kept;
  kept.reserve(chosen.size());
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    StepSources sources = raw[chosen[i]];
    if (i > 0 && chosen[i - 1] + 1 != chosen[i]) {
      const SourceLine& first = raw[chosen[i - 1] + 1].odometry;
      if (first.file == sources.odometry.file) {
        sources.odometry.firstLine = first.firstLine != 0 ? first.firstLine : first.line;
      }
    }
    kept.push_back(std::move(sources));
  }
  return kept;
}

}  // namespace

std::string datasetFile(const std::string& folder, const std::string& name) {
  if (!std::filesystem::is_directory(folder)) {
    throw InputError(folder, 0, "not a folder (the converter reads the dataset's folder, which holds " + name + ")");
  }
  return (std::filesystem::path(folder) / name).string();
}

std::vector<NumericRow> readDatasetTable(const std::string& path, std::size_t columns, const std::string& names) {
  std::vector<NumericRow> rows = readNumericTable(path, Separator::Whitespace);
  if (rows.empty()) throw InputError(path, 0, "no data rows (expected rows of: " + names + ")");
  for (const NumericRow& row : rows) {
    if (row.values.size() != columns) {
      throw InputError(path, row.line,
                       "expected " + std::to_string(columns) + " numbers (" + names + "), found " +
                           std::to_string(row.values.size()));
    }
  }
  return rows;
}

int integerField(const std::string& path, const NumericRow& row, std::size_t column, const std::string& name,
                 int minimum, int maximum) {
  const double value = row.values.at(column);
  if (value != std::floor(value) || value < minimum || value > maximum) {
    std::ostringstream problem;
    problem << name << " " << value << " is not an integer in [" << minimum << ", " << maximum << "]";
    throw InputError(path, row.line, problem.str());
  }
  return static_cast<int>(value);
}

std::set<int> readLandmarkTruthTable(const std::string& path, int dimension, std::size_t columns,
                                    const std::string& names, const std::string& idName,
                                    std::vector<LandmarkTruth>& truth, std::vector<SourceLine>& rows) {
  std::set<int> ids;
  for (const NumericRow& row : readDatasetTable(path, columns, names)) {
    LandmarkTruth landmark;
    landmark.id = integerField(path, row, 0, idName, 0, 1 << 30);
    if (dimension == 2) {
      landmark.state = Point2(row.values[1], row.values[2]);
    } else {
      landmark.state = Point3(row.values[1], row.values[2], row.values[3]);
    }
    if (!ids.insert(landmark.id).second) {
      throw InputError(path, row.line, idName + " " + std::to_string(landmark.id) + " appears twice");
    }
    truth.push_back(landmark);
    rows.push_back(SourceLine{path, row.line, 0});
  }
  return ids;
}

std::optional<std::size_t> findStep(const std::vector<TimeStep>& steps, double time, double tolerance) {
  const auto it = std::lower_bound(steps.begin(), steps.end(), time - tolerance,
                                   [](const TimeStep& step, double t) { return step.time < t; });
  if (it == steps.end() || it->time > time + tolerance) return std::nullopt;
  return static_cast<std::size_t>(it - steps.begin());
}

Matrix diagonalCovariance(const std::vector<double>& values) {
  Matrix covariance = Matrix::Zero(static_cast<Eigen::Index>(values.size()), static_cast<Eigen::Index>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)) = values[i];
  }
  return covariance;
}

MeasurementLog finishConversion(MeasurementLog raw, LogSources sources, const ConvertOptions& options,
                                ConversionStats* stats) {
  const int dimension = raw.header.dimension;
  validateConvertOptions(options, dimension);
  if (sources.steps.size() != raw.steps.size()) {
    throw std::invalid_argument("finishConversion: the sources are not parallel to the steps");
  }
  if (raw.steps.empty()) throw InputError(sources.dataset, 0, "the dataset has no time steps");
  ConversionStats counts;
  counts.datasetSteps = raw.steps.size();
  for (const TimeStep& step : raw.steps) counts.datasetDetections += step.detections.size();

  MeasurementLog log;
  log.header = std::move(raw.header);
  if (options.keyframePeriod > 0.0) {
    KeyframeSummary summary;
    log.steps = selectKeyframes(raw.steps, options.keyframePeriod, &summary);
    sources.steps = keyframeSources(sources.steps, summary.chosen);
    counts.stepsDroppedByKeyframing = summary.droppedSteps;
    counts.detectionsDroppedByKeyframing = summary.droppedDetections;
  } else {
    log.steps = std::move(raw.steps);
  }
  const std::size_t before = log.steps.size();
  counts.detectionsDroppedByMaxSteps = keepFirstSteps(log.steps, options.maxSteps);
  counts.stepsDroppedByMaxSteps = before - log.steps.size();
  sources.steps.resize(log.steps.size());

  if (log.header.semantic == SemanticKind::None) {
    assignClassLabels(log, options.classes, options.misclassification, options.seed, options.clutterLabels);
  } else if (options.classes != 1 || options.misclassification != 0.0) {
    // The dataset's own labels (kitti-tracking: the detector's class) are kept as they are.
    throw InputError("--classes and --misclassification do not apply: this dataset has its own class labels");
  }

  // Priors.
  const int tangent = dimension == 3 ? 6 : 3;
  PosePrior prior;
  const std::optional<Pose>& firstTruth = log.steps.front().truePose;
  if (firstTruth) {
    prior.mean = *firstTruth;
  } else if (dimension == 3) {
    prior.mean = SE3();
  } else {
    prior.mean = SE2();
  }
  std::vector<double> variances(static_cast<std::size_t>(tangent), kDefaultInitialPoseSigma * kDefaultInitialPoseSigma);
  for (std::size_t i = 0; i < options.initialPoseSigmas.size(); ++i) {
    variances[i] = options.initialPoseSigmas[i] * options.initialPoseSigmas[i];
  }
  prior.covariance = diagonalCovariance(variances);
  log.header.initialPose = prior;
  log.header.landmarkPriors.clear();
  if (options.mapPriorSigma > 0.0) {
    const double variance = options.mapPriorSigma * options.mapPriorSigma;
    for (const LandmarkTruth& truth : log.header.landmarkTruth) {
      LandmarkPrior landmark;
      landmark.id = truth.id;
      landmark.mean = truth.state;
      const bool point3 = std::holds_alternative<Point3>(truth.state);
      const bool point2 = std::holds_alternative<Point2>(truth.state);
      const int size = point2 ? 2 : point3 ? 3 : std::holds_alternative<SE2>(truth.state) ? 3 : 6;
      landmark.covariance = variance * Matrix::Identity(size, size);
      log.header.landmarkPriors.push_back(std::move(landmark));
    }
  }

  // Counts of what is written.
  counts.steps = log.steps.size();
  counts.landmarks = log.header.landmarkTruth.size();
  for (const TimeStep& step : log.steps) {
    counts.detections += step.detections.size();
    if (step.truePose) ++counts.truePoses;
    for (const Detection& detection : step.detections) {
      if (detection.truthId && *detection.truthId == kNotALandmark) ++counts.clutter;
      if (detection.truthId && *detection.truthId == kUnknownTruth) ++counts.unknownTruth;
    }
  }

  std::ostringstream source;
  source << log.header.source << "; settings: " << describeConvertOptions(options, dimension);
  source << "; initial pose prior at " << (firstTruth ? "the first true pose" : "the identity (no true first pose)");
  source << "; dataset " << counts.datasetSteps << " steps, " << counts.datasetDetections << " detections";
  if (options.keyframePeriod > 0.0) {
    source << "; keyframing dropped " << counts.stepsDroppedByKeyframing << " steps and "
           << counts.detectionsDroppedByKeyframing << " detections";
  }
  if (counts.stepsDroppedByMaxSteps > 0) {
    source << "; max-steps dropped " << counts.stepsDroppedByMaxSteps << " steps and "
           << counts.detectionsDroppedByMaxSteps << " detections";
  }
  source << "; written " << counts.steps << " steps, " << counts.detections << " detections (" << counts.clutter
         << " clutter";
  if (counts.unknownTruth > 0) source << ", " << counts.unknownTruth << " unknown";
  source << ")";
  log.header.source = source.str();
  checkConvertedLog(log, sources);
  if (stats != nullptr) *stats = counts;
  return log;
}

}  // namespace semslam
