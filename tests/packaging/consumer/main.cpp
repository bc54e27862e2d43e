// Solves a three-pose loop through the installed semslam and prints the optimised chi2: proof that headers,
// library and the CMake package work together outside the source tree.

#include <cstdio>

#include <semslam/factors/BetweenFactor.h>
#include <semslam/factors/PriorFactor.h>
#include <semslam/solve/Optimizer.h>

int main() {
  using namespace semslam;
  FactorGraph graph;
  Values initial;
  const auto noise = NoiseModel::fromSigmas(Vector3(0.1, 0.1, 0.05));
  graph.emplace<PriorFactor<SE2>>(poseKey(0), SE2(), NoiseModel::isotropic(3, 1e-3));
  graph.emplace<BetweenFactor<SE2>>(poseKey(0), poseKey(1), SE2(1.0, 0.0, 2.1), noise);
  graph.emplace<BetweenFactor<SE2>>(poseKey(1), poseKey(2), SE2(1.0, 0.0, 2.1), noise);
  graph.emplace<BetweenFactor<SE2>>(poseKey(2), poseKey(0), SE2(1.0, 0.0, 2.1), noise);
  for (int i = 0; i < 3; ++i) initial.insert(poseKey(i), SE2(i, i, 0.0));
  const OptimizationResult result = optimize(graph, initial);
  std::printf("consumer: chi2 %.6g -> %.6g, converged %d\n", result.initialChi2, result.finalChi2, result.converged);
  return result.converged && result.finalChi2 < result.initialChi2 ? 0 : 1;
}
