#pragma once
// SemanticSimulationTruth: the true trajectory a semantic simulation (sim/SemanticSimulator.h) runs along, as
// `semslam simulate semantic` chooses it: a generated path (sim/GeneratedPath.h; loop or lawnmower, seeded from
// the run's seed) when no file is given, else a TUM or KITTI trajectory file read here (io/TrajectoryFormat.h) and
// turned into a simulation truth by sim/TrajectoryInput.h (frame, stride, step limit, time step). It also writes
// the one-line description the log's header records as its source; simulateSemanticRun then simulates the log.
// In io/ because it reads trajectory files.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "semslam/models/MeasurementLog.h"
#include "semslam/sim/SemanticSimulator.h"
#include "semslam/sim/SimTrajectory.h"

namespace semslam {

struct SemanticTruthOptions {
  int dimension = 2;
  std::string trajectory;        ///< a file; empty: a generated path
  std::string trajectoryFormat;  ///< tum | kitti (required with a file)
  std::string trajectoryFrame;   ///< body | camera; empty: camera for kitti, body for tum
  int stride = 1;                ///< file: keep every stride-th pose
  std::string path = "loop";     ///< generated: loop | lawnmower
  std::optional<int> steps;      ///< generated: default 200; file: 0 (the default) = all
  double stepLength = 1.0;
  int loops = 2;
  double rowLength = 30.0;
  double rowSpacing = 6.0;
  double heightAmplitude = 1.0;
  std::optional<double> timeStep;  ///< generated: default 1 s; file without times: 0.1 s
};

struct SemanticTruth {
  SimTrajectory trajectory;
  std::string description;  ///< e.g. "loop path (200 steps of 1 m, 2 loops)"
};

/// Throws InputError for inconsistent options or a bad file.
SemanticTruth semanticSimulationTruth(const SemanticTruthOptions& options, std::uint64_t seed);

struct SemanticSimulation {
  MeasurementLog log;
  std::string description;  ///< the truth's description (SemanticTruth)
};

/// `semslam simulate semantic`: validates `sim` (InputError naming the first bad option), chooses the truth as
/// above and simulates the log along it (sim/SemanticSimulator.h) with the truth's description as its source.
/// `progress` as in simulateSemantic.
SemanticSimulation simulateSemanticRun(const SemanticTruthOptions& truth, SemanticSimOptions sim, std::uint64_t seed,
                                       const std::function<void(int done, int total)>& progress = {});

}  // namespace semslam
