// semslam eval ate|rpe: trajectory error metrics exactly as evo (MichaelGrupp/evo) defines them — absolute pose
// error (evo_ape) and relative pose error (evo_rpe) with evo's association, alignment and statistics. See
// src/semslam/eval/TrajectoryEvaluation.h, io/TrajectoryErrorReport.h (the reading and the two printed forms) and
// docs/evaluation.md.

#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "semslam/io/TrajectoryErrorReport.h"

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

void run(const EvalOptions& o) {
  TrajectoryErrorRequest request;
  request.relative = o.relative;
  request.reference = o.reference;
  request.estimate = o.estimate;
  request.estimateFormat = parseTrajectoryFormat(o.estimateFormat.empty() ? o.format : o.estimateFormat);
  request.referenceFormat = parseTrajectoryFormat(o.referenceFormat.empty() ? o.format : o.referenceFormat);
  EvaluationOptions& options = request.options;
  options.relation = parsePoseRelation(o.relation);
  options.alignment = parseAlignmentMode(o.align);
  options.maxTimeDifference = o.maxTimeDifference;
  options.timeOffset = o.timeOffset;
  options.delta = o.delta;
  options.deltaUnit = parseDeltaUnit(o.deltaUnit);
  options.allPairs = o.allPairs;
  options.relativeDeltaTolerance = o.deltaTolerance;
  options.pairsFromReference = o.pairsFromReference;
  const EvaluationResult result = evaluateTrajectoryFiles(request);
  const std::string text = o.json ? trajectoryErrorJson(request, result) : trajectoryErrorText(request, result);
  std::fputs(text.c_str(), stdout);
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
