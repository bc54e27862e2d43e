// semslam convert KIND PATH --out LOG: a real dataset to a measurement log (docs/datasets.md).

#include <array>
#include <cstdio>
#include <memory>
#include <map>
#include <string>
#include <vector>

#include "Commands.h"
#include "OptionValidators.h"
#include "semslam/core/InputError.h"
#include "semslam/io/convert/DatasetConverters.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/OutputTarget.h"

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
  bool commandDelayGiven = false;
  bool kittiGiven = false;  // a kitti-tracking option was given
  std::array<double, 3> scoreThresholds{};  // given where the option was given
  double odometryNoiseScale = 1.0;
};

void run(ConvertArguments arguments) {
  ConvertOptions& options = arguments.options;
  options.initialPoseSigmas = arguments.initialPoseSigmas;
  options.maxSteps = arguments.maxSteps;
  if (arguments.robotGiven && arguments.kind != "mrclam") {
    throw InputError("--robot applies to mrclam only, not to " + arguments.kind);
  }
  if (arguments.commandDelayGiven && arguments.kind != "mrclam") {
    throw InputError("--command-delay applies to mrclam only, not to " + arguments.kind);
  }
  if (arguments.kittiGiven && arguments.kind != "kitti-tracking") {
    throw InputError("--sequence, --score-threshold-*, --odometry, --odom-noise-scale, --max-range, --confusion and "
                     "--matches-out apply to kitti-tracking only, not to " +
                     arguments.kind);
  }
  requireOutputSparesInput(arguments.out, arguments.path, "--out");
  requireReplaceableFile(arguments.out);
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
  for (const std::string& note : stats.notes) std::printf("  %s\n", note.c_str());
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto arguments = std::make_shared<ConvertArguments>();
  CLI::App* command = app.add_subcommand(
      "convert", "Convert a real dataset (../shared/data) to a measurement log; docs/datasets.md describes each");
  command->add_option("KIND", arguments->kind,
                      "utias-lost-in-the-woods, utias-starry-night, mrclam, isam or kitti-tracking")
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
  command->add_option("--max-steps", arguments->maxSteps, "keep the first N steps (0: all)")
      ->check(unsignedInteger64())  // CLI11 wraps "-5" around and saturates past 2^64 - 1
      ->capture_default_str();
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
  CLI::Option* commandDelay =
      command
          ->add_option("--command-delay", arguments->options.commandDelay,
                       "mrclam: seconds from a command's stamp to the motion it causes (docs/datasets.md)")
          ->capture_default_str();
  KittiTrackingOptions& kitti = arguments->options.kitti;
  std::vector<CLI::Option*> kittiOptions = {
      command->add_option("--sequence", kitti.sequence, "kitti-tracking: the sequence number (label_02/NNNN.txt)"),
      command->add_option("--score-threshold-car", arguments->scoreThresholds[0],
                          "kitti-tracking: drop Car detections with a lower score (default: docs/datasets.md)"),
      command->add_option("--score-threshold-pedestrian", arguments->scoreThresholds[1],
                          "kitti-tracking: drop Pedestrian detections with a lower score"),
      command->add_option("--score-threshold-cyclist", arguments->scoreThresholds[2],
                          "kitti-tracking: drop Cyclist detections with a lower score"),
      command
          ->add_option("--odometry", kitti.odometry,
                       "kitti-tracking: orbslam (ORB-SLAM3's relative motion) or noisy (plus seeded noise, --seed)")
          ->transform(CLI::CheckedTransformer(std::map<std::string, KittiTrackingOptions::Odometry>{
              {"orbslam", KittiTrackingOptions::Odometry::OrbSlam},
              {"noisy", KittiTrackingOptions::Odometry::Noisy}}))
          ->default_str("orbslam"),
      command->add_option("--odom-noise-scale", arguments->odometryNoiseScale,
                          "kitti-tracking, --odometry noisy: noise of K times ORB-SLAM's stated sigmas (default 1)"),
      command->add_option("--max-range", kitti.maxRange,
                          "kitti-tracking: drop detections beyond this range in metres; the sensor's max range (0: "
                          "none)"),
      command->add_option("--confusion", kitti.confusionFile,
                          "kitti-tracking: a 3x3 count table (rows true Car, Pedestrian, Cyclist; columns detected) "
                          "to estimate the misclassification rate from, instead of this sequence's own matches"),
      command->add_option("--matches-out", kitti.matchesOut,
                          "kitti-tracking: write each kept detection's match, truth kind and residual to this CSV"),
  };
  command->callback([arguments, robot, commandDelay, kittiOptions]() {
    ConvertArguments copy = *arguments;
    copy.robotGiven = robot->count() > 0;
    copy.commandDelayGiven = commandDelay->count() > 0;
    for (const CLI::Option* option : kittiOptions) copy.kittiGiven = copy.kittiGiven || option->count() > 0;
    for (std::size_t c = 0; c < 3; ++c) {  // kittiOptions[1..3]: the thresholds
      if (kittiOptions[1 + c]->count() > 0) copy.options.kitti.scoreThresholds[c] = copy.scoreThresholds[c];
    }
    if (kittiOptions[5]->count() > 0) copy.options.kitti.odometryNoiseScale = copy.odometryNoiseScale;
    run(std::move(copy));
  });
}

}  // namespace semslam::cli
