#include "semslam/io/SemanticSimulationTruth.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "semslam/core/InputError.h"
#include "semslam/io/TrajectoryFormat.h"
#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SimulationStreams.h"
#include "semslam/sim/TrajectoryInput.h"

namespace semslam {

namespace {

SemanticTruth generatedTruth(const SemanticTruthOptions& options, std::uint64_t seed) {
  if (!options.trajectoryFormat.empty() || !options.trajectoryFrame.empty() || options.stride != 1) {
    throw InputError("--trajectory-format, --trajectory-frame and --stride apply to --trajectory FILE only");
  }
  PathOptions path;
  path.shape = parsePathShape(options.path);
  path.dimension = options.dimension;
  path.steps = options.steps.value_or(200);
  path.stepLength = options.stepLength;
  path.loops = options.loops;
  path.rowLength = options.rowLength;
  path.rowSpacing = options.rowSpacing;
  path.heightAmplitude = options.heightAmplitude;
  path.timeStep = options.timeStep.value_or(1.0);
  if (path.steps < 1) throw InputError("--steps: must be >= 1 for a generated path");
  char text[160];
  std::snprintf(text, sizeof text, "%s path (%d steps of %g m%s)", options.path.c_str(), path.steps, path.stepLength,
                path.shape == PathShape::Loop ? (", " + std::to_string(path.loops) + " loops").c_str() : "");
  std::mt19937 rng = simulationStream(seed, 0, SimStream::Path);
  try {
    return {generatePath(path, rng), text};
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
}

SemanticTruth fileTruth(const SemanticTruthOptions& options) {
  if (options.trajectoryFormat.empty()) throw InputError("--trajectory needs --trajectory-format tum|kitti");
  const TrajectoryFormat format = parseTrajectoryFormat(options.trajectoryFormat);
  TrajectoryInputOptions input;
  input.dimension = options.dimension;
  input.frame = options.trajectoryFrame.empty()
                    ? (format == TrajectoryFormat::Kitti ? TrajectoryFrame::Camera : TrajectoryFrame::Body)
                    : parseTrajectoryFrame(options.trajectoryFrame);
  input.stride = options.stride;
  input.maxSteps = options.steps.value_or(0);
  input.timeStep = options.timeStep.value_or(0.1);
  if (input.maxSteps < 0) throw InputError("--steps: must be >= 0 (0: the whole file)");
  const Trajectory trajectory = readTrajectory(options.trajectory, format);
  const std::string description =
      "trajectory " + std::filesystem::path(options.trajectory).filename().string() + " (" +
      options.trajectoryFormat + ", " + (input.frame == TrajectoryFrame::Camera ? "camera" : "body") +
      " frame, stride " + std::to_string(input.stride) + ")";
  return {simTrajectoryFromFile(trajectory, input, options.trajectory), description};
}

}  // namespace

SemanticTruth semanticSimulationTruth(const SemanticTruthOptions& options, std::uint64_t seed) {
  return options.trajectory.empty() ? generatedTruth(options, seed) : fileTruth(options);
}

}  // namespace semslam

namespace semslam {

SemanticSimulation simulateSemanticRun(const SemanticTruthOptions& truthOptions, SemanticSimOptions sim,
                                       std::uint64_t seed, const std::function<void(int, int)>& progress) {
  try {
    validateSemanticSimOptions(sim);
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
  SemanticTruth truth = semanticSimulationTruth(truthOptions, seed);
  sim.description = truth.description;
  return {simulateSemantic(truth.trajectory, sim, seed, progress), std::move(truth.description)};
}

}  // namespace semslam
