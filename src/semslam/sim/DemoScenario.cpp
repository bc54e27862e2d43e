#include "semslam/sim/DemoScenario.h"

#include "semslam/sim/SimulationStreams.h"

namespace semslam {

DemoScenario demoScenarioOptions() {
  DemoScenario scenario;
  scenario.path.shape = PathShape::Loop;
  scenario.path.dimension = 2;
  scenario.path.steps = 240;
  scenario.path.stepLength = 0.5;
  scenario.path.loops = 2;
  SemanticSimOptions& sim = scenario.sim;
  sim.classes = 3;
  sim.landmarks = 30;
  sim.minOffset = 1.0;
  sim.maxOffset = 3.0;
  sim.maxRange = 6.0;
  sim.fieldOfView = 2.0;
  sim.rangeSigma = 0.15;
  sim.bearingSigma = 0.03;
  sim.detectionProbability = 0.9;
  sim.misclassification = 0.1;
  sim.odomNoiseScale = 1.0;
  sim.clutter = 0.1;
  sim.description = "semslam demo: a seeded loop driven twice among look-alike landmarks";
  return scenario;
}

MeasurementLog simulateDemoLog(std::uint64_t seed) {
  const DemoScenario scenario = demoScenarioOptions();
  std::mt19937 rng = simulationStream(seed, 0, SimStream::Path);
  return simulateSemantic(generatePath(scenario.path, rng), scenario.sim, seed);
}

}  // namespace semslam
