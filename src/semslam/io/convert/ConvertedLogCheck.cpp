#include "semslam/io/convert/ConvertedLogCheck.h"

#include <stdexcept>
#include <string>

#include "semslam/core/InputError.h"
#include "semslam/io/JsonField.h"
#include "semslam/io/MeasurementLogJson.h"

namespace semslam {

using jsonio::Json;
using jsonio::JsonField;
using jsonio::JsonLocation;

namespace {

const char* const kRefused = "the log made from it would be refused";

/// `source`, or the dataset as a whole where no row was recorded.
SourceLine orDataset(const SourceLine& source, const LogSources& sources) {
  if (!source.file.empty()) return source;
  return SourceLine{sources.dataset, 0, 0};
}

[[noreturn]] void refuse(const SourceLine& source, const std::string& record, const InputError& error) {
  std::string problem = std::string(kRefused) + " (" + record + "): " + error.problem();
  if (source.firstLine != 0 && source.firstLine != source.line) {
    problem += " (the odometry of lines " + std::to_string(source.firstLine) + " to " + std::to_string(source.line) +
               ", composed by --keyframe-period)";
  }
  throw InputError(source.file, source.line, problem);
}

bool headerAccepted(const LogHeader& header) {
  const JsonLocation location{"", 1};
  const Json json = jsonio::headerToJson(header);
  try {
    jsonio::headerFromJson(JsonField(json, location));
    return true;
  } catch (const InputError&) {
    return false;
  }
}

/// The row behind a refused header: when the header without its landmarks is refused, the first true pose if the
/// initial pose prior (made at that pose) is what it refuses, else the sensor's row; otherwise the first landmark
/// refused alone (with its map prior).
SourceLine headerCulprit(const MeasurementLog& log, const LogSources& sources) {
  LogHeader bare = log.header;
  bare.landmarkTruth.clear();
  bare.landmarkPriors.clear();
  if (!headerAccepted(bare)) {
    LogHeader withoutPrior = bare;
    withoutPrior.initialPose.reset();
    if (log.header.initialPose && headerAccepted(withoutPrior) && !sources.steps.empty()) {
      return orDataset(sources.steps.front().truePose, sources);
    }
    return orDataset(sources.sensor, sources);
  }
  for (std::size_t i = 0; i < log.header.landmarkTruth.size(); ++i) {
    LogHeader one = bare;
    one.landmarkTruth.push_back(log.header.landmarkTruth[i]);
    for (const LandmarkPrior& prior : log.header.landmarkPriors) {
      if (prior.id == log.header.landmarkTruth[i].id) one.landmarkPriors.push_back(prior);
    }
    if (!headerAccepted(one)) return orDataset(sources.landmarks[i], sources);
  }
  return SourceLine{sources.dataset, 0, 0};
}

bool stepAccepted(const jsonio::StepParser& parser, const TimeStep& step, SemanticKind semantic) {
  jsonio::StepParser trial = parser;  // a copy: the parser keeps the previous time and the step count
  const JsonLocation location{"", 0};
  const Json json = jsonio::stepToJson(step, semantic);
  try {
    trial.parse(JsonField(json, location));
    return true;
  } catch (const InputError&) {
    return false;
  }
}

/// The step's time and, where it has odometry, an identity increment with a unit covariance: a record every
/// parser accepts unless the time itself is refused.
TimeStep bareStep(const TimeStep& step, int dimension) {
  TimeStep bare;
  bare.time = step.time;
  if (step.odometry) {
    Odometry identity;
    if (dimension == 2) {
      identity.increment = SE2();
    } else {
      identity.increment = SE3();
    }
    const int tangent = dimension == 2 ? 3 : 6;
    identity.covariance = Matrix::Identity(tangent, tangent);
    bare.odometry = identity;
  }
  return bare;
}

/// The row behind a refused step: its time's row, its odometry's, its true pose's or a detection's, whichever part
/// is refused on its own (tried on a copy of `parser`, which is left as it was); else the step's own row.
SourceLine stepCulprit(const jsonio::StepParser& parser, const TimeStep& step, const StepSources& sources,
                       const LogHeader& header, const LogSources& all) {
  const TimeStep bare = bareStep(step, header.dimension);
  if (!stepAccepted(parser, bare, header.semantic)) return orDataset(sources.step, all);
  if (step.odometry) {
    TimeStep part = bare;
    part.odometry = step.odometry;
    if (!stepAccepted(parser, part, header.semantic)) return orDataset(sources.odometry, all);
  }
  if (step.truePose) {
    TimeStep part = bare;
    part.truePose = step.truePose;
    if (!stepAccepted(parser, part, header.semantic)) return orDataset(sources.truePose, all);
  }
  for (std::size_t j = 0; j < step.detections.size(); ++j) {
    TimeStep part = bare;
    part.detections.push_back(step.detections[j]);
    if (!stepAccepted(parser, part, header.semantic)) return orDataset(sources.detections[j], all);
  }
  return orDataset(sources.step, all);
}

void requireParallel(const MeasurementLog& log, const LogSources& sources) {
  bool parallel = sources.steps.size() == log.steps.size() &&
                  sources.landmarks.size() == log.header.landmarkTruth.size();
  for (std::size_t k = 0; parallel && k < log.steps.size(); ++k) {
    parallel = sources.steps[k].detections.size() == log.steps[k].detections.size();
  }
  if (!parallel) throw std::invalid_argument("checkConvertedLog: the sources are not parallel to the log");
}

}  // namespace

void checkConvertedLog(const MeasurementLog& log, const LogSources& sources) {
  requireParallel(log, sources);
  if (log.steps.empty()) throw InputError(sources.dataset, 0, std::string(kRefused) + ": no time steps");
  const JsonLocation location{"", 1};
  LogHeader header;
  {
    const Json json = jsonio::headerToJson(log.header);
    try {
      header = jsonio::headerFromJson(JsonField(json, location));
    } catch (const InputError& error) {
      refuse(headerCulprit(log, sources), "header", error);
    }
  }
  jsonio::StepParser parser(header);
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    const Json json = jsonio::stepToJson(log.steps[k], log.header.semantic);
    try {
      parser.parse(JsonField(json, location));
    } catch (const InputError& error) {
      refuse(stepCulprit(parser, log.steps[k], sources.steps[k], header, sources), "log step " + std::to_string(k),
             error);
    }
  }
}

}  // namespace semslam
