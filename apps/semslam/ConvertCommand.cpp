// semslam convert KIND PATH --out LOG: a real dataset to a measurement log (docs/datasets.md).

#include <cstdio>
#include <memory>
#include <map>
#include <string>
#include <vector>

#include "Commands.h"
#include "semslam/core/InputError.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/convert/DatasetConverters.h"

namespace semslam::cli {

namespace {

struct ConvertArguments {
  std::string kind;
  std::string path;
  std::string out;
  ConvertOptions options;
  std::vector<double> initialPoseSigmas;
  std::size_t maxSteps = 0;
  bool robotGiven = false;
};

void run(ConvertArguments arguments) {
  ConvertOptions& options = arguments.options;
  options.initialPoseSigmas = arguments.initialPoseSigmas;
  options.maxSteps = arguments.maxSteps;
  if (arguments.robotGiven && arguments.kind != "mrclam") {
    throw InputError("--robot applies to mrclam only, not to " + arguments.kind);
  }
  ConversionStats stats;
  const MeasurementLog log = convertDataset(arguments.kind, arguments.path, options, &stats);
  writeMeasurementLog(arguments.out, log);
  std::printf(
      "wrote %s: %s, %zu steps, %zu detections (%zu clutter, %zu unknown), %zu landmarks, %zu true poses; dataset "
      "%zu steps, %zu detections; dropped by keyframing %zu detections, by --max-steps %zu\n",
      arguments.out.c_str(), arguments.kind.c_str(), stats.steps, stats.detections, stats.clutter,
      stats.unknownTruth, stats.landmarks,
      stats.truePoses, stats.datasetSteps, stats.datasetDetections, stats.detectionsDroppedByKeyframing,
      stats.detectionsDroppedByMaxSteps);
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto arguments = std::make_shared<ConvertArguments>();
  CLI::App* command = app.add_subcommand(
      "convert", "Convert a real dataset (../shared/data) to a measurement log; docs/datasets.md describes each");
  command->add_option("KIND", arguments->kind, "utias-lost-in-the-woods, utias-starry-night, mrclam or isam")
      ->required()
      ->check(CLI::IsMember(datasetKinds()));
  command->add_option("PATH", arguments->path, "the dataset folder (isam: the .txt file)")->required();
  command->add_option("--out", arguments->out, "the measurement log to write (JSON lines)")->required();
  command
      ->add_option("--classes", arguments->options.classes,
                   "number of classes M; a landmark's class is its id mod M (1: no semantic part)")
      ->capture_default_str();
  command
      ->add_option("--misclassification", arguments->options.misclassification,
                   "categorical model's misclassification rate p of the sampled labels")
      ->capture_default_str();
  command
      ->add_option("--clutter-labels", arguments->options.clutterLabels,
                   "labels of clutter: uniform (no information) or per-source (one class per known source, e.g. "
                   "MRCLAM's robots, misclassified at the same rate)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, ClutterLabels>{
          {"uniform", ClutterLabels::Uniform}, {"per-source", ClutterLabels::PerSource}}))
      ->default_str("uniform");
  command->add_option("--seed", arguments->options.seed, "seed of the label draws")->capture_default_str();
  command
      ->add_option("--keyframe-period", arguments->options.keyframePeriod,
                   "keep one step per period in seconds, composing the odometry in between (0: every step)")
      ->capture_default_str();
  command->add_option("--max-steps", arguments->maxSteps, "keep the first N steps (0: all)")->capture_default_str();
  command
      ->add_option("--initial-pose-sigma", arguments->initialPoseSigmas,
                   "standard deviations of the first-pose prior: sx,sy,stheta (3D: sx,sy,sz,srx,sry,srz); default "
                   "0.001 each")
      ->delimiter(',');
  command
      ->add_option("--map-prior", arguments->options.mapPriorSigma,
                   "put the landmark ground truth into the header as a prior map with this standard deviation "
                   "(metres; 0: none)")
      ->capture_default_str();
  CLI::Option* robot =
      command->add_option("--robot", arguments->options.robot, "mrclam: the robot 1..5")->capture_default_str();
  command->callback([arguments, robot]() {
    ConvertArguments copy = *arguments;
    copy.robotGiven = robot->count() > 0;
    run(std::move(copy));
  });
}

}  // namespace semslam::cli
