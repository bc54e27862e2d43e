// semslam check LOG: validates a measurement log (docs/measurement-log.md) and prints its summary.

#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "Commands.h"
#include "semslam/eval/MeasurementResiduals.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam::cli {

namespace {

struct LogSummary {
  std::size_t steps = 0;
  std::size_t detections = 0;
  std::size_t minPerStep = std::numeric_limits<std::size_t>::max();
  std::size_t maxPerStep = 0;
  std::size_t withTruth = 0;
  std::size_t clutter = 0;
  std::size_t truePoses = 0;
  std::size_t withOdometry = 0;
  double firstTime = 0.0;
  double lastTime = 0.0;
};

std::string sensorText(const SensorSpec& sensor) {
  std::string text(sensorKindName(sensor.kind));
  char buffer[96];
  if (sensor.maxRange > 0.0) {
    std::snprintf(buffer, sizeof buffer, ", max range %g m", sensor.maxRange);
    text += buffer;
  } else {
    text += ", unlimited range";
  }
  if (sensor.fieldOfView > 0.0) {
    std::snprintf(buffer, sizeof buffer, ", field of view %g rad", sensor.fieldOfView);
    text += buffer;
  } else {
    text += ", all around";
  }
  return text;
}

std::string classifierText(const ClassifierModelSpec& classifier) {
  std::string text(classifierKindName(classifier.kind));
  char buffer[96] = "";
  if (classifier.kind == ClassifierModelSpec::Kind::Categorical) {
    std::snprintf(buffer, sizeof buffer, " (misclassification %g)", classifier.misclassification);
  } else if (classifier.kind == ClassifierModelSpec::Kind::ViewpointGaussian) {
    std::snprintf(buffer, sizeof buffer, " (alpha %g, sharpness %g)", classifier.alpha, classifier.sharpness);
  }
  text += buffer;
  if (!classifier.table.empty()) text += ", table " + classifier.table;
  return text;
}

void run(const std::string& path, bool residuals) {
  MeasurementLogReader reader(path);
  const LogHeader& header = reader.header();
  std::optional<ResidualAccumulator> accumulator;
  if (residuals) accumulator.emplace(header);
  LogSummary summary;
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
    }
    if (step.truePose) ++summary.truePoses;
    if (step.odometry) ++summary.withOdometry;
  }

  std::printf("%s: valid %s, version %d\n", path.c_str(), std::string(kMeasurementLogFormat).c_str(),
              header.version);
  std::printf("dimension:     %dD, landmarks are %s\n", header.dimension, header.landmarksHavePose ? "poses" : "points");
  std::printf("sensor:        %s\n", sensorText(header.sensor).c_str());
  std::printf("classes:       %d, semantic %s, classifier %s\n", header.classes,
              std::string(semanticKindName(header.semantic)).c_str(), classifierText(header.classifier).c_str());
  std::printf("steps:         %zu (%zu with odometry, %zu with a true pose)\n", summary.steps, summary.withOdometry,
              summary.truePoses);
  std::printf("duration:      %.6g s (time %.17g to %.17g)\n", summary.lastTime - summary.firstTime,
              summary.firstTime, summary.lastTime);
  std::printf("detections:    %zu; per step min %zu, mean %.4g, max %zu\n", summary.detections, summary.minPerStep,
              static_cast<double>(summary.detections) / static_cast<double>(summary.steps), summary.maxPerStep);
  std::printf("ground truth:  %zu landmarks; %zu detections with truth (%zu of a landmark, %zu clutter), %zu without\n",
              header.landmarkTruth.size(), summary.withTruth, summary.withTruth - summary.clutter, summary.clutter,
              summary.detections - summary.withTruth);
  std::printf("priors:        initial pose %s; %zu landmark priors\n", header.initialPose ? "yes" : "no",
              header.landmarkPriors.size());
  if (!header.source.empty()) std::printf("source:        %s\n", header.source.c_str());
  if (accumulator) {
    std::printf("residuals against the ground truth (docs/datasets.md):\n%s",
                formatResidualStatistics(accumulator->statistics()).c_str());
  }
}

}  // namespace

void addCheckCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto residuals = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand(
      "check", "Validate a measurement log (docs/measurement-log.md) and print its summary; exit 2 if it is bad");
  command->add_option("LOG", *path, "measurement log (JSON lines)")->required();
  command->add_flag("--residuals", *residuals,
                    "also print the residuals of detections and odometry against the log's ground truth");
  command->callback([path, residuals]() { run(*path, *residuals); });
}

}  // namespace semslam::cli
