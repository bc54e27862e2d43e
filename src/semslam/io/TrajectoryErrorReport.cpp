#include "semslam/io/TrajectoryErrorReport.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "semslam/core/InputError.h"
#include "semslam/core/Version.h"

namespace semslam {

namespace {

std::string relationTitle(PoseRelation relation) {
  switch (relation) {
    case PoseRelation::TranslationPart: return "translation part (m)";
    case PoseRelation::AngleDeg: return "rotation angle (deg)";
    case PoseRelation::AngleRad: return "rotation angle (rad)";
    case PoseRelation::RotationPart: return "rotation part (unit-less)";
    case PoseRelation::Full: return "full transformation (unit-less)";
  }
  return "";
}

std::string alignmentTitle(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::None: return "(not aligned)";
    case AlignmentMode::Se3: return "(with SE(3) Umeyama alignment)";
    case AlignmentMode::Sim3: return "(with Sim(3) Umeyama alignment)";
    case AlignmentMode::Scale: return "(scale corrected)";
    case AlignmentMode::Origin: return "(with origin alignment)";
  }
  return "";
}

std::string formatDelta(double delta, DeltaUnit unit) {
  std::ostringstream s;
  if (unit == DeltaUnit::Frames) {
    s << static_cast<long long>(delta);
  } else {
    s << delta;
    if (s.str().find_first_of(".e") == std::string::npos) s << ".0";  // evo prints the float: 10.0
  }
  return s.str();
}

bool scaled(const EvaluationOptions& options) {
  return options.alignment == AlignmentMode::Sim3 || options.alignment == AlignmentMode::Scale;
}

bool finiteStatistics(const ErrorStatistics& s) {
  return std::isfinite(s.max) && std::isfinite(s.mean) && std::isfinite(s.median) && std::isfinite(s.min) &&
         std::isfinite(s.rmse) && std::isfinite(s.sse) && std::isfinite(s.std);
}

/// The pose of `trajectory` with the largest coordinate (in magnitude), and that magnitude.
std::pair<std::size_t, double> largestCoordinate(const Trajectory& trajectory) {
  std::pair<std::size_t, double> largest{0, 0.0};
  for (std::size_t k = 0; k < trajectory.size(); ++k) {
    const double magnitude = trajectory.position(k).cwiseAbs().maxCoeff();
    if (magnitude > largest.second) largest = {k, magnitude};
  }
  return largest;
}

}  // namespace

EvaluationResult evaluateTrajectoryFiles(const TrajectoryErrorRequest& request) {
  const Trajectory reference = readTrajectory(request.reference, request.referenceFormat);
  const Trajectory estimate = readTrajectory(request.estimate, request.estimateFormat);
  EvaluationResult result = request.relative ? evaluateRelativePoseError(reference, estimate, request.options)
                                             : evaluateAbsolutePoseError(reference, estimate, request.options);
  if (!finiteStatistics(result.statistics)) {
    // Finite coordinates whose squares or sums overflow (a TUM coordinate of 1e308): the input's doing.
    const auto [estimatePose, estimateMagnitude] = largestCoordinate(estimate);
    const auto [referencePose, referenceMagnitude] = largestCoordinate(reference);
    const bool estimateLarger = estimateMagnitude >= referenceMagnitude;
    std::ostringstream problem;
    problem << "the error statistics overflow (not finite): the coordinates are too large; the largest, "
            << (estimateLarger ? estimateMagnitude : referenceMagnitude) << ", is in pose "
            << (estimateLarger ? estimatePose : referencePose) << " (0-based) of this file";
    throw InputError(estimateLarger ? request.estimate : request.reference, 0, problem.str());
  }
  return result;
}

std::string trajectoryErrorText(const TrajectoryErrorRequest& request, const EvaluationResult& result) {
  const EvaluationOptions& options = request.options;
  const ErrorStatistics& s = result.statistics;
  std::string title = (request.relative ? "RPE w.r.t. " : "APE w.r.t. ") + relationTitle(options.relation);
  if (request.relative) {
    title += "\nfor delta = " + formatDelta(options.delta, options.deltaUnit) + " (" + toString(options.deltaUnit) +
             ")" + (options.allPairs ? " using all pairs" : " using consecutive pairs");
  }
  title += "\n" + alignmentTitle(options.alignment);
  std::string text = title + "\n\n";
  const std::pair<const char*, double> rows[] = {{"max", s.max},   {"mean", s.mean}, {"median", s.median},
                                                 {"min", s.min},   {"rmse", s.rmse}, {"sse", s.sse},
                                                 {"std", s.std}};
  char line[128];
  for (const auto& [name, value] : rows) {
    std::snprintf(line, sizeof line, "%10s\t%.6f\n", name, value);
    text += line;
  }
  std::snprintf(line, sizeof line, "\n%zu %s compared (%zu associated poses)", s.count,
                request.relative ? "pose pairs" : "poses", result.associatedPoses);
  text += line;
  if (scaled(options)) {
    std::snprintf(line, sizeof line, ", scale correction %.6f", result.alignment.scale);
    text += line;
  }
  return text + "\n";
}

std::string trajectoryErrorJson(const TrajectoryErrorRequest& request, const EvaluationResult& result) {
  const EvaluationOptions& options = request.options;
  const ErrorStatistics& s = result.statistics;
  nlohmann::json out;
  out["metric"] = request.relative ? "rpe" : "ape";
  out["relation"] = toString(options.relation);
  out["unit"] = unitOf(options.relation);
  out["align"] = toString(options.alignment);
  out["reference"] = request.reference;
  out["estimate"] = request.estimate;
  out["rmse"] = s.rmse;
  out["mean"] = s.mean;
  out["median"] = s.median;
  out["max"] = s.max;
  out["min"] = s.min;
  out["sse"] = s.sse;
  out["std"] = s.std;
  out["pairs"] = s.count;
  out["associated_poses"] = result.associatedPoses;
  out["version"] = std::string(version());
  if (scaled(options)) out["scale"] = result.alignment.scale;
  if (request.relative) {
    out["delta"] = options.delta;
    out["delta_unit"] = toString(options.deltaUnit);
    out["all_pairs"] = options.allPairs;
  }
  return out.dump(2) + "\n";
}

}  // namespace semslam
