#include "semslam/io/MeasurementLogSummary.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "semslam/io/MeasurementLogFile.h"

namespace semslam {

namespace {

/// printf-style formatting into a string.
__attribute__((format(printf, 1, 2))) std::string format(const char* pattern, ...) {
  va_list arguments;
  va_start(arguments, pattern);
  va_list copy;
  va_copy(copy, arguments);
  const int size = std::vsnprintf(nullptr, 0, pattern, copy);
  va_end(copy);
  std::string text(static_cast<std::size_t>(std::max(size, 0)) + 1, '\0');
  std::vsnprintf(text.data(), text.size(), pattern, arguments);
  va_end(arguments);
  text.pop_back();
  return text;
}

std::string sensorText(const SensorSpec& sensor) {
  std::string text(sensorKindName(sensor.kind));
  text += sensor.maxRange > 0.0 ? format(", max range %g m", sensor.maxRange) : ", unlimited range";
  text += sensor.fieldOfView > 0.0 ? format(", field of view %g rad", sensor.fieldOfView) : ", all around";
  return text;
}

std::string classifierText(const ClassifierModelSpec& classifier) {
  std::string text(classifierKindName(classifier.kind));
  if (classifier.kind == ClassifierModelSpec::Kind::Categorical) {
    text += format(" (misclassification %g)", classifier.misclassification);
  } else if (classifier.kind == ClassifierModelSpec::Kind::ViewpointGaussian) {
    text += format(" (alpha %g, sharpness %g)", classifier.alpha, classifier.sharpness);
  }
  if (!classifier.table.empty()) text += ", table " + classifier.table;
  return text;
}

}  // namespace

MeasurementLogSummary summarizeMeasurementLog(const std::string& path, bool residuals) {
  MeasurementLogReader reader(path);
  MeasurementLogSummary summary;
  summary.path = path;
  summary.header = reader.header();
  std::optional<ResidualAccumulator> accumulator;
  if (residuals) accumulator.emplace(summary.header);
  TimeStep step;
  while (reader.next(step)) {
    if (accumulator) accumulator->add(step);
    if (summary.steps == 0) summary.firstTime = step.time;
    summary.lastTime = step.time;
    ++summary.steps;
    const std::size_t n = step.detections.size();
    summary.detections += n;
    summary.minPerStep = std::min(summary.minPerStep, n);
    summary.maxPerStep = std::max(summary.maxPerStep, n);
    for (const Detection& detection : step.detections) {
      if (!detection.truthId) continue;
      ++summary.withTruth;
      if (*detection.truthId == kNotALandmark) ++summary.clutter;
      if (*detection.truthId == kUnknownTruth) ++summary.unknownTruth;
    }
    if (step.truePose) ++summary.truePoses;
    if (step.odometry) ++summary.withOdometry;
  }
  if (accumulator) summary.residuals = accumulator->statistics();
  return summary;
}

std::string formatMeasurementLogSummary(const MeasurementLogSummary& s) {
  const LogHeader& header = s.header;
  std::string text;
  text += format("%s: valid %s, version %d\n", s.path.c_str(), std::string(kMeasurementLogFormat).c_str(),
                 header.version);
  text += format("dimension:     %dD, landmarks are %s\n", header.dimension,
                 header.landmarksHavePose ? "poses" : "points");
  text += format("sensor:        %s\n", sensorText(header.sensor).c_str());
  text += format("classes:       %d, semantic %s, classifier %s\n", header.classes,
                 std::string(semanticKindName(header.semantic)).c_str(), classifierText(header.classifier).c_str());
  text += format("steps:         %zu (%zu with odometry, %zu with a true pose)\n", s.steps, s.withOdometry,
                 s.truePoses);
  text += format("duration:      %.6g s (time %.17g to %.17g)\n", s.lastTime - s.firstTime, s.firstTime, s.lastTime);
  text += format("detections:    %zu; per step min %zu, mean %.4g, max %zu\n", s.detections, s.minPerStep,
                 static_cast<double>(s.detections) / static_cast<double>(s.steps), s.maxPerStep);
  text += format("ground truth:  %zu landmarks; %zu detections with truth (%zu of a landmark, %zu clutter, %zu "
                 "unknown), %zu without\n",
                 header.landmarkTruth.size(), s.withTruth, s.withTruth - s.clutter - s.unknownTruth, s.clutter,
                 s.unknownTruth, s.detections - s.withTruth);
  text += format("priors:        initial pose %s; %zu landmark priors\n", header.initialPose ? "yes" : "no",
                 header.landmarkPriors.size());
  if (!header.source.empty()) text += format("source:        %s\n", header.source.c_str());
  if (s.residuals) {
    text += "residuals against the ground truth (docs/datasets.md):\n" + formatResidualStatistics(*s.residuals);
  }
  return text;
}

}  // namespace semslam
