// semslam simulate aliased2d|semantic: seeded, deterministic measurement logs (docs/simulators.md).
//
//   aliased2d  paper A's perceptually aliased scenario: N tracks of K steps from one start (src/semslam/sim/
//              Aliased2dSimulator.h), the scenario from --scenario FILE, a generated layout (--layout-seed S,
//              sim/Aliased2dLayout.h) or the built-in default.
//              Several tracks go to a folder (io/Aliased2dTrackFolder.h).
//   semantic   paper B-style runs in 2D or 3D along a generated path or a TUM/KITTI trajectory
//              (src/semslam/sim/SemanticSimulator.h; the truth and the run: io/SemanticSimulationTruth.h).

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "Commands.h"
#include "OptionValidators.h"
#include "semslam/core/InputError.h"
#include "semslam/core/ProgressBar.h"
#include "semslam/io/Aliased2dTrackFolder.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/OutputTarget.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/io/SemanticSimulationTruth.h"
#include "semslam/sim/Aliased2dLayout.h"
#include "semslam/sim/Aliased2dSimulator.h"
#include "semslam/sim/Aliased3dLift.h"

namespace semslam::cli {

namespace {

namespace fs = std::filesystem;

// ---- aliased2d ----

struct AliasedOptions {
  std::string scenario;
  std::optional<std::uint64_t> layoutSeed;
  int tracks = 1;
  int steps = 10;
  std::uint64_t seed = 1;
  std::optional<double> alpha;
  std::string out;
  std::string writeScenario;
  bool quiet = false;
  bool overwrite = false;
  bool lift3d = false;                 // sim/Aliased3dLift.h: the track in 3D, level
  std::vector<double> objectHeights;   // ... with the objects at these heights (implies lift3d)
};

Aliased2dScenario scenarioOf(const AliasedOptions& options) {
  if (!options.scenario.empty()) return readAliased2dScenario(options.scenario);
  if (options.layoutSeed) return generatedAliased2dScenario(*options.layoutSeed);
  return defaultAliased2dScenario();
}

void runAliased(const AliasedOptions& options) {
  if (!options.scenario.empty()) {
    if (!options.out.empty()) requireOutputSparesInput(options.out, options.scenario, "--out");
    if (!options.writeScenario.empty()) {
      requireOutputSparesInput(options.writeScenario, options.scenario, "--write-scenario");
    }
  }
  Aliased2dScenario scenario = scenarioOf(options);
  if (options.alpha) {
    if (!(*options.alpha >= 0.0 && *options.alpha <= 1.0)) {
      throw InputError("--alpha: must be in [0, 1], found " + std::to_string(*options.alpha));
    }
    scenario.alpha = *options.alpha;
  }
  if (!options.writeScenario.empty()) {
    writeAliased2dScenario(options.writeScenario, scenario);
    std::printf("wrote scenario '%s' to %s\n", scenario.name.c_str(), options.writeScenario.c_str());
  }
  if (options.out.empty()) {
    if (options.writeScenario.empty()) throw InputError("--out is required (or --write-scenario alone)");
    return;
  }
  if (options.tracks == 1) {
    if (fs::is_directory(options.out)) {
      throw InputError("--out " + options.out + ": is a folder; with one track --out names the log file");
    }
    MeasurementLog log = simulateAliased2dTrack(scenario, options.seed, 0, options.steps, 1);
    if (options.lift3d || !options.objectHeights.empty()) {
      if (!options.objectHeights.empty() && options.objectHeights.size() != scenario.objects.size()) {
        throw InputError("--object-heights: " + std::to_string(options.objectHeights.size()) +
                         " heights for the scenario's " + std::to_string(scenario.objects.size()) + " objects");
      }
      Aliased3dLift lift;
      lift.objectHeights = options.objectHeights;
      log = liftAliasedLogTo3d(log, lift, options.seed, 0);
    }
    writeMeasurementLog(options.out, log);
    std::printf("wrote 1 track of %d steps (scenario '%s', seed %llu%s) to %s\n", options.steps,
                scenario.name.c_str(), static_cast<unsigned long long>(options.seed),
                log.header.dimension == 3 ? ", in 3D" : "", options.out.c_str());
    return;
  }
  if (options.lift3d || !options.objectHeights.empty()) {
    throw InputError("--lift-3d and --object-heights: one track at a time (--tracks 1)");
  }
  // One line rewritten in place on a terminal, a line every few seconds otherwise (core/ProgressBar.h).
  ProgressBar progress("simulate aliased2d tracks", options.tracks, options.quiet);
  writeAliased2dTrackFolder(options.out, scenario, options.seed, options.tracks, options.steps, options.overwrite,
                            [&progress](int done, int) { progress.update(done); });
  std::printf("wrote %d tracks of %d steps (scenario '%s', seed %llu) to %s/\n", options.tracks, options.steps,
              scenario.name.c_str(), static_cast<unsigned long long>(options.seed), options.out.c_str());
}

void addAliased(CLI::App& simulate) {
  auto options = std::make_shared<AliasedOptions>();
  CLI::App* command = simulate.add_subcommand(
      "aliased2d", "Paper A's perceptually aliased 2D scenario: sampled tracks from one start (docs/simulators.md)");
  CLI::Option* scenario =
      command->add_option("--scenario", options->scenario, "scenario JSON file (default: the built-in parking aisle)")
          ->check(CLI::ExistingFile);
  command
      ->add_option("--layout-seed", options->layoutSeed,
                   "a generated layout instead (six objects in three translated pairs; docs/simulators.md)")
      ->check(unsignedInteger64())
      ->excludes(scenario);
  command->add_option("--tracks", options->tracks, "number of ground-truth tracks")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  command->add_option("--steps", options->steps, "steps per track after the start")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--seed", options->seed, "random seed (unsigned 64-bit)")
      ->check(unsignedInteger64())
      ->capture_default_str();
  command->add_option("--alpha", options->alpha, "classifier viewpoint dependency (overrides the scenario's)");
  command->add_option("--out", options->out, "the log (one track) or a folder of track_NNN.jsonl (several)");
  command->add_option("--write-scenario", options->writeScenario,
                      "write the scenario in effect (after --alpha) as JSON to this file");
  command->add_flag("--lift-3d", options->lift3d,
                    "the track in 3D: SE3 poses, range-bearing-elevation, level (sim/Aliased3dLift.h)");
  command->add_option("--object-heights", options->objectHeights,
                      "in 3D with the objects at these heights in metres, one per object (implies --lift-3d)")
      ->delimiter(',')
      ->check(CLI::Range(-1e4, 1e4));
  command->add_flag("--quiet", options->quiet, "no progress line");
  command->add_flag("--overwrite", options->overwrite,
                    "several tracks: replace an existing non-empty --out folder whole");
  command->callback([options]() { runAliased(*options); });
}

// ---- semantic ----

struct SemanticCliOptions {
  std::string out;
  bool quiet = false;
  std::uint64_t seed = 1;
  SemanticTruthOptions truth;
  SemanticSimOptions sim;
};

void runSemantic(const SemanticCliOptions& options) {
  if (!options.truth.trajectory.empty()) requireOutputSparesInput(options.out, options.truth.trajectory, "--out");
  // A long trajectory file (KITTI 00: 4541 poses) takes seconds: one progress line (core/ProgressBar.h), made at
  // the first step, when the number of steps is known.
  std::optional<ProgressBar> progress;
  SemanticSimulation simulation;
  try {
    simulation =
        simulateSemanticRun(options.truth, options.sim, options.seed, [&progress, &options](int done, int total) {
          if (!progress) progress.emplace("simulate semantic", total, options.quiet);
          progress->update(done);
        });
  } catch (const std::invalid_argument& error) {  // an option out of range: bad input
    throw InputError(std::string("simulate semantic: ") + error.what());
  }
  const MeasurementLog& log = simulation.log;
  writeMeasurementLog(options.out, log);
  std::size_t detections = 0;
  for (const TimeStep& step : log.steps) detections += step.detections.size();
  std::printf("wrote %zu steps, %zu landmarks, %zu detections (%dD, %s, seed %llu) to %s\n", log.steps.size(),
              log.header.landmarkTruth.size(), detections, options.truth.dimension, simulation.description.c_str(),
              static_cast<unsigned long long>(options.seed), options.out.c_str());
}

void addSemantic(CLI::App& simulate) {
  auto options = std::make_shared<SemanticCliOptions>();
  SemanticCliOptions& o = *options;
  CLI::App* command = simulate.add_subcommand(
      "semantic", "Paper B-style semantic SLAM run in 2D or 3D: landmarks with classes, labels, clutter");
  command->add_option("--out", o.out, "the log to write")->required();
  command->add_option("--seed", o.seed, "random seed (unsigned 64-bit)")
      ->check(unsignedInteger64())
      ->capture_default_str();
  SemanticTruthOptions& t = o.truth;
  command->add_option("--dimension", t.dimension, "2 or 3")->check(CLI::IsMember({2, 3}))->capture_default_str();
  command->add_option("--trajectory", t.trajectory, "true trajectory file (default: a generated path)")
      ->check(CLI::ExistingFile);
  command->add_option("--trajectory-format", t.trajectoryFormat, "tum or kitti")
      ->check(CLI::IsMember({"tum", "kitti"}));
  command
      ->add_option("--trajectory-frame", t.trajectoryFrame,
                   "body or camera (poses of a z-forward camera); default camera for kitti, body for tum")
      ->check(CLI::IsMember({"body", "camera"}));
  command->add_option("--stride", t.stride, "keep every N-th pose of the file")->check(CLI::Range(1, 1000000));
  command->add_option("--path", t.path, "generated path: loop (seeded) or lawnmower")
      ->check(CLI::IsMember({"loop", "lawnmower"}))
      ->capture_default_str();
  command->add_option("--steps", t.steps, "steps after the first pose (generated: default 200; file: 0 = all)")
      ->check(CLI::Range(0, 1000000));
  command->add_option("--step-length", t.stepLength, "generated path: metres per step")->capture_default_str();
  command->add_option("--loops", t.loops, "loop path: times around")->capture_default_str();
  command->add_option("--row-length", t.rowLength, "lawnmower: row length (m)")->capture_default_str();
  command->add_option("--row-spacing", t.rowSpacing, "lawnmower: row spacing (m)")->capture_default_str();
  command->add_option("--height-amplitude", t.heightAmplitude, "3D loop: height undulation (m)")->capture_default_str();
  command->add_option("--time-step", t.timeStep, "seconds per step (generated: 1; file without times: 0.1)");
  SemanticSimOptions& s = o.sim;
  command->add_option("--classes", s.classes, "number of classes M")
      ->check(CLI::Range(1, 2048))
      ->capture_default_str();
  command->add_option("--landmarks", s.landmarks, "number of landmarks (0: from --landmark-density)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  command->add_option("--landmark-density", s.landmarkDensity, "landmarks per metre of path")->capture_default_str();
  command->add_option("--min-offset", s.minOffset, "landmarks' least lateral distance from the path (m)")
      ->capture_default_str();
  command->add_option("--max-offset", s.maxOffset, "landmarks' largest lateral distance from the path (m)")
      ->capture_default_str();
  command->add_option("--min-height", s.minHeight, "3D: landmarks' least height above the path (m)")
      ->capture_default_str();
  command->add_option("--max-height", s.maxHeight, "3D: landmarks' largest height above the path (m)")
      ->capture_default_str();
  command->add_option("--max-range", s.maxRange, "sensor range (m; 0: unlimited)")->capture_default_str();
  command->add_option("--field-of-view", s.fieldOfView, "sensor field of view, full angle (rad; 0: all around)")
      ->capture_default_str();
  command->add_option("--range-sigma", s.rangeSigma, "range noise (m)")->capture_default_str();
  command->add_option("--bearing-sigma", s.bearingSigma, "bearing noise (rad)")->capture_default_str();
  command->add_option("--elevation-sigma", s.elevationSigma, "3D: elevation noise (rad)")->capture_default_str();
  command->add_option("--detection-probability", s.detectionProbability, "probability a visible landmark is detected")
      ->capture_default_str();
  command->add_option("--misclassification", s.misclassification, "probability a label is wrong")
      ->capture_default_str();
  command->add_option("--odom-noise-scale", s.odomNoiseScale, "odometry noise = scale x the baseline")
      ->capture_default_str();
  command->add_option("--odom-covariance-scale", s.odomCovarianceScale,
                      "covariance stated in the log = scale^2 x baseline (default: the noise scale)");
  command->add_option("--clutter", s.clutter, "mean false detections per step (Poisson)")->capture_default_str();
  command->add_flag("--quiet", o.quiet, "no progress line");
  command->callback([options]() { runSemantic(*options); });
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  CLI::App* simulate = app.add_subcommand("simulate", "Simulate measurement logs, seeded and deterministic");
  simulate->require_subcommand(1);
  addAliased(*simulate);
  addSemantic(*simulate);
}

}  // namespace semslam::cli
