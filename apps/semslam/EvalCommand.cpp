// semslam eval ate|rpe: trajectory error metrics exactly as evo (MichaelGrupp/evo) defines them — absolute pose
// error (evo_ape) and relative pose error (evo_rpe) with evo's association, alignment and statistics. See
// src/semslam/eval/TrajectoryEvaluation.h and docs/evaluation.md.

#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "Commands.h"
#include "semslam/eval/TrajectoryEvaluation.h"
#include "semslam/io/TrajectoryFormat.h"
#include "semslam/core/InputError.h"

namespace semslam::cli {

namespace {

struct EvalOptions {
  bool relative = false;  // rpe instead of ate
  std::string estimate;
  std::string reference;
  std::string format = "tum";
  std::string estimateFormat;
  std::string referenceFormat;
  std::string align = "none";
  std::string relation = "trans_part";
  double maxTimeDifference = 0.01;
  double timeOffset = 0.0;
  double delta = 1.0;
  std::string deltaUnit = "frames";
  bool allPairs = false;
  double deltaTolerance = 0.1;
  bool pairsFromReference = false;
  bool json = false;
};

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

void run(const EvalOptions& o) {
  const TrajectoryFormat estimateFormat = parseTrajectoryFormat(o.estimateFormat.empty() ? o.format : o.estimateFormat);
  const TrajectoryFormat referenceFormat =
      parseTrajectoryFormat(o.referenceFormat.empty() ? o.format : o.referenceFormat);

  EvaluationOptions options;
  options.relation = parsePoseRelation(o.relation);
  options.alignment = parseAlignmentMode(o.align);
  options.maxTimeDifference = o.maxTimeDifference;
  options.timeOffset = o.timeOffset;
  options.delta = o.delta;
  options.deltaUnit = parseDeltaUnit(o.deltaUnit);
  options.allPairs = o.allPairs;
  options.relativeDeltaTolerance = o.deltaTolerance;
  options.pairsFromReference = o.pairsFromReference;

  const Trajectory reference = readTrajectory(o.reference, referenceFormat);
  const Trajectory estimate = readTrajectory(o.estimate, estimateFormat);
  const EvaluationResult result = o.relative ? evaluateRelativePoseError(reference, estimate, options)
                                             : evaluateAbsolutePoseError(reference, estimate, options);
  const ErrorStatistics& s = result.statistics;
  const bool scaled = options.alignment == AlignmentMode::Sim3 || options.alignment == AlignmentMode::Scale;

  if (o.json) {
    nlohmann::json out;
    out["metric"] = o.relative ? "rpe" : "ape";
    out["relation"] = toString(options.relation);
    out["unit"] = unitOf(options.relation);
    out["align"] = toString(options.alignment);
    out["reference"] = o.reference;
    out["estimate"] = o.estimate;
    out["rmse"] = s.rmse;
    out["mean"] = s.mean;
    out["median"] = s.median;
    out["max"] = s.max;
    out["min"] = s.min;
    out["sse"] = s.sse;
    out["std"] = s.std;
    out["pairs"] = s.count;
    out["associated_poses"] = result.associatedPoses;
    if (scaled) out["scale"] = result.alignment.scale;
    if (o.relative) {
      out["delta"] = options.delta;
      out["delta_unit"] = toString(options.deltaUnit);
      out["all_pairs"] = options.allPairs;
    }
    std::cout << out.dump(2) << "\n";
    return;
  }

  // evo's Result.pretty_str: the title, a blank line, then the statistics sorted by name as "%10s\t%.6f".
  std::string title = (o.relative ? "RPE w.r.t. " : "APE w.r.t. ") + relationTitle(options.relation);
  if (o.relative) {
    title += "\nfor delta = " + formatDelta(options.delta, options.deltaUnit) + " (" + toString(options.deltaUnit) +
             ")" + (options.allPairs ? " using all pairs" : " using consecutive pairs");
  }
  title += "\n" + alignmentTitle(options.alignment);
  std::printf("%s\n\n", title.c_str());
  const std::pair<const char*, double> rows[] = {{"max", s.max},   {"mean", s.mean}, {"median", s.median},
                                                 {"min", s.min},   {"rmse", s.rmse}, {"sse", s.sse},
                                                 {"std", s.std}};
  for (const auto& [name, value] : rows) std::printf("%10s\t%.6f\n", name, value);
  std::printf("\n%zu %s compared (%zu associated poses)", s.count, o.relative ? "pose pairs" : "poses",
              result.associatedPoses);
  if (scaled) std::printf(", scale correction %.6f", result.alignment.scale);
  std::printf("\n");
}

void addMetric(CLI::App& eval, const std::string& name, bool relative, const std::string& description) {
  auto options = std::make_shared<EvalOptions>();
  options->relative = relative;
  CLI::App* sub = eval.add_subcommand(name, description);
  if (!relative) sub->alias("ape");
  sub->add_option("--est", options->estimate, "estimated trajectory file")->required();
  sub->add_option("--ref", options->reference, "reference (ground-truth) trajectory file")->required();
  const auto formats = CLI::IsMember({"tum", "kitti", "euroc"});
  sub->add_option("--format", options->format, "format of both files: tum, kitti or euroc")
      ->capture_default_str()
      ->check(formats);
  sub->add_option("--est-format", options->estimateFormat, "format of the estimate (overrides --format)")
      ->check(formats);
  sub->add_option("--ref-format", options->referenceFormat, "format of the reference (overrides --format)")
      ->check(formats);
  sub->add_option("--align", options->align,
                  "alignment of the estimate: none, se3 (Umeyama), sim3 (Umeyama with scale), scale (scale only), "
                  "origin (first poses)")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "se3", "sim3", "scale", "origin"}));
  sub->add_option("--relation,-r", options->relation,
                  "pose relation: trans_part, angle_deg, angle_rad, rot_part, full")
      ->capture_default_str()
      ->check(CLI::IsMember({"trans_part", "angle_deg", "angle_rad", "rot_part", "full"}));
  sub->add_option("--t-max-diff", options->maxTimeDifference, "maximum timestamp difference for association (s)")
      ->capture_default_str();
  sub->add_option("--t-offset", options->timeOffset, "time offset added to the estimate's timestamps (s)")
      ->capture_default_str();
  if (relative) {
    sub->add_option("--delta,-d", options->delta, "distance between the poses of a pair")->capture_default_str();
    sub->add_option("--delta-unit,-u", options->deltaUnit,
                    "unit of --delta: frames, or m (path length along the estimated trajectory)")
        ->capture_default_str()
        ->check(CLI::IsMember({"frames", "f", "m"}));
    sub->add_flag("--all-pairs", options->allPairs, "use all pairs instead of consecutive pairs");
    sub->add_option("--delta-tol", options->deltaTolerance, "relative delta tolerance for --all-pairs with m")
        ->capture_default_str();
    sub->add_flag("--pairs-from-reference", options->pairsFromReference,
                  "choose the pairs on the reference instead of the estimate");
  }
  sub->add_flag("--json", options->json, "print the result as a JSON object");
  sub->callback([options]() { run(*options); });
}

}  // namespace

void addEvalCommand(CLI::App& app) {
  CLI::App* eval = app.add_subcommand("eval", "trajectory error metrics as evo defines them (APE/ATE, RPE)");
  eval->require_subcommand(1);
  addMetric(*eval, "ate", false,
            "absolute pose error (evo_ape): associate, align, compare poses; statistics of the errors");
  addMetric(*eval, "rpe", true, "relative pose error (evo_rpe): compare relative motions between pose pairs");
}

}  // namespace semslam::cli
