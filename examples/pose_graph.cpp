// Example 1: a 2D pose graph, optimised with semslam's own engine.
//
// A robot drives twice around a 4 m square in 1 m steps. Its odometry is noisy, so chaining it (dead reckoning)
// drifts; on the second lap it recognises the places of the first lap (loop closures). We put the odometry and
// the loop closures into a factor graph, optimise it with Levenberg-Marquardt, read the uncertainty of the last
// pose, and check that the loop closures pulled the trajectory back towards the truth.
//
// Read with: README.md ("The library"), docs/solver.md (the optimizers, their stopping rules, marginals),
// docs/file-formats.md (the same graph read from a g2o/TORO/iSAM file: `semslam optimize FILE`).
// Conventions: SE2 poses (x, y, θ); a noise model's sigmas are over the tangent, translation first.
//
// Exit code 0 when the optimised trajectory is accurate (the checks at the end), 1 otherwise: `make test` runs
// this program as the ctest examples.pose_graph.

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <semslam/factors/BetweenFactor.h>
#include <semslam/factors/PriorFactor.h>
#include <semslam/solve/Marginals.h>
#include <semslam/solve/Optimizer.h>

using namespace semslam;

namespace {

constexpr int kStepsPerLap = 16;  // 4 sides of 4 one-metre steps
constexpr int kLaps = 2;
constexpr int kPoses = kStepsPerLap * kLaps + 1;

// The true pose after `step` steps: straight 1 m steps, a 90° left turn at every corner.
SE2 truePose(int step) {
  SE2 pose;  // starts at the origin, heading along +x
  for (int k = 0; k < step; ++k) {
    const bool corner = (k + 1) % 4 == 0;
    pose = pose * SE2(1.0, 0.0, corner ? std::numbers::pi / 2 : 0.0);
  }
  return pose;
}

// The root-mean-square position error of `values` against the truth, over every pose.
double positionRmse(const Values& values) {
  double sum = 0.0;
  for (int i = 0; i < kPoses; ++i) {
    const Point2 error = values.at<SE2>(poseKey(i)).translation() - truePose(i).translation();
    sum += error.squaredNorm();
  }
  return std::sqrt(sum / kPoses);
}

}  // namespace

int main() {
  std::mt19937 rng(7);  // a fixed seed: the same output on every run
  std::normal_distribution<double> unit(0.0, 1.0);

  // 1. Noise models: the odometry is good to 5 cm and 1° per step; a loop closure (a place recognised) to 2 cm.
  const Vector3 odometrySigmas(0.05, 0.05, 0.0175);
  const Vector3 loopSigmas(0.02, 0.02, 0.01);
  const SharedNoiseModel odometryNoise = NoiseModel::fromSigmas(odometrySigmas);
  const SharedNoiseModel loopNoise = NoiseModel::fromSigmas(loopSigmas);
  // A measurement of the relative pose a⁻¹ b, perturbed on the right by noise of the given sigmas.
  const auto measure = [&](const SE2& a, const SE2& b, const Vector3& sigmas) {
    const Vector3 noise(sigmas.x() * unit(rng), sigmas.y() * unit(rng), sigmas.z() * unit(rng));
    return a.between(b) * SE2::Exp(noise);
  };

  // 2. The factor graph. Poses are keys x0, x1, ... (poseKey). A prior on x0 fixes the gauge: without it the
  //    whole trajectory could slide and turn freely and the optimizer would report an unconstrained system.
  FactorGraph graph;
  graph.emplace<PriorFactor<SE2>>(poseKey(0), SE2(), NoiseModel::isotropic(3, 1e-3));
  Values initial;            // the starting point of the optimisation: dead reckoning
  initial.insert(poseKey(0), SE2());
  SE2 deadReckoning;
  for (int i = 1; i < kPoses; ++i) {
    const SE2 odometry = measure(truePose(i - 1), truePose(i), odometrySigmas);
    graph.emplace<BetweenFactor<SE2>>(poseKey(i - 1), poseKey(i), odometry, odometryNoise);
    deadReckoning = deadReckoning * odometry;
    initial.insert(poseKey(i), deadReckoning);
  }
  // 3. Loop closures: on the second lap, pose i is at the place of pose i − kStepsPerLap.
  for (int i = kStepsPerLap; i < kPoses; ++i) {
    const int earlier = i - kStepsPerLap;
    graph.emplace<BetweenFactor<SE2>>(poseKey(earlier), poseKey(i), measure(truePose(earlier), truePose(i), loopSigmas),
                                      loopNoise);
  }
  std::printf("pose graph: %d poses, %zu factors (1 prior, %d odometry, %d loop closures)\n", kPoses, graph.size(),
              kPoses - 1, kPoses - kStepsPerLap);

  // 4. Optimise. Levenberg-Marquardt recovers from a poor start where Gauss-Newton may not (docs/solver.md).
  OptimizerParams params;
  params.solver = SolverType::LevenbergMarquardt;
  const OptimizationResult result = optimize(graph, initial, params);
  std::printf("chi2 %.4g -> %.4g in %d iterations (%s)\n", result.initialChi2, result.finalChi2, result.iterations,
              result.stopReason.c_str());

  // 5. How far from the truth? Dead reckoning drifts; the loop closures pull the estimate back.
  const double driftError = positionRmse(initial);
  const double optimisedError = positionRmse(result.values);
  std::printf("position RMSE against the truth: dead reckoning %.3f m, optimised %.3f m\n", driftError,
              optimisedError);

  // 6. Uncertainty: the marginal covariance of the last pose at the optimum (tangent: x, y, θ).
  const Marginals marginals(graph, result.values);
  const SE2& last = result.values.at<SE2>(poseKey(kPoses - 1));
  const Matrix lastCovariance = marginals.marginalCovariance(poseKey(kPoses - 1));
  std::printf("last pose: (%.3f, %.3f, %.3f rad), sigma x %.3f m, y %.3f m, theta %.4f rad\n", last.x(), last.y(),
              last.theta(), std::sqrt(lastCovariance(0, 0)), std::sqrt(lastCovariance(1, 1)),
              std::sqrt(lastCovariance(2, 2)));

  // 7. The checks `make test` relies on. At the optimum, chi2 is a sample of a χ² distribution with
  //    (residuals − unknowns) = 3 · 50 − 3 · 33 = 51 degrees of freedom when the noise models are right, so it
  //    should lie well below 2 · 51 (its 99.99 % quantile is about 97); the loop closures must at least halve the
  //    dead-reckoning error.
  const double degreesOfFreedom = 3.0 * static_cast<double>(graph.size()) - 3.0 * kPoses;
  const bool ok = result.converged && result.finalChi2 < 2.0 * degreesOfFreedom &&
                  optimisedError < 0.5 * driftError;
  std::printf("%s\n", ok ? "OK" : "FAILED: the optimised trajectory is not where it should be");
  return ok ? 0 : 1;
}
