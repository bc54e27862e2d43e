// A downstream program of an installed semslam (tests/packaging/install_and_consume.sh builds it with CMake and
// with pkg-config): solves a three-pose loop, so headers, library, CHOLMOD and Eigen work together outside the
// source tree, and checks that the library's version is the one the package claims (argument 1).
// Exit 0 only when the solve converged, lowered chi2, and the version matches.

#include <cstdio>
#include <string>

#include <semslam/core/Version.h>
#include <semslam/factors/BetweenFactor.h>
#include <semslam/factors/PriorFactor.h>
#include <semslam/solve/Optimizer.h>

int main(int argc, char** argv) {
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
  const std::string libraryVersion(version());
  std::printf("consumer: semslam %s, chi2 %.6g -> %.6g, converged %d\n", libraryVersion.c_str(), result.initialChi2,
              result.finalChi2, result.converged);
  if (argc > 1 && libraryVersion != argv[1]) {
    std::fprintf(stderr, "consumer: the library says version %s, the package %s\n", libraryVersion.c_str(), argv[1]);
    return 1;
  }
  return result.converged && result.finalChi2 < result.initialChi2 ? 0 : 1;
}
