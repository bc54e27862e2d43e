#pragma once
// DemoScenario: the built-in semantic log of `semslam demo`, small enough to solve in a few seconds and hard
// enough that data association matters. A 2D robot drives a seeded 60 m loop twice (240 steps of 0.5 m; loop
// closures: it must recognise landmarks it saw a lap ago) among 30 look-alike landmarks standing close together
// 1 to 3 m beside its path (three classes, so neighbouring landmarks often share one), with a wrong class label
// one time in ten, a false detection every ten steps (clutter), missed detections (one in ten) and noisy odometry.
// Built by the semantic simulator (SemanticSimulator.h) along a generated loop (GeneratedPath.h); the numbers are
// in demoScenarioOptions().

#include <cstdint>

#include "semslam/models/MeasurementLog.h"
#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"

namespace semslam {

struct DemoScenario {
  PathOptions path;
  SemanticSimOptions sim;
};

/// The demo's path and simulator options.
DemoScenario demoScenarioOptions();

/// The demo's log for `seed` (deterministic).
MeasurementLog simulateDemoLog(std::uint64_t seed);

}  // namespace semslam
