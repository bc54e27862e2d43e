#include "semslam/run/KnownTrajectoryCeiling.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "semslam/geometry/Manifold.h"
#include "semslam/models/PosteriorSampler.h"
#include "semslam/models/Sampling.h"

namespace semslam {
namespace {

int tangentDimension(const Pose& pose) { return std::holds_alternative<SE2>(pose) ? 3 : 6; }

Matrix pinnedCovariance(const Pose& pose) {
  const int d = tangentDimension(pose);
  return Matrix::Identity(d, d) * (kPinnedSigma * kPinnedSigma);
}

Pose motionBetween(const Pose& from, const Pose& to) {
  if (const auto* se2 = std::get_if<SE2>(&from)) return se2->between(std::get<SE2>(to));
  return std::get<SE3>(from).between(std::get<SE3>(to));
}

}  // namespace

MeasurementLog logOnTrajectory(const MeasurementLog& log, const std::vector<Pose>& trajectory) {
  if (trajectory.size() != log.steps.size()) {
    throw std::invalid_argument("logOnTrajectory: " + std::to_string(trajectory.size()) + " poses for " +
                                std::to_string(log.steps.size()) + " steps");
  }
  MeasurementLog pinned = log;
  if (trajectory.empty()) return pinned;
  pinned.header.initialPose = PosePrior{trajectory.front(), pinnedCovariance(trajectory.front())};
  for (std::size_t k = 1; k < pinned.steps.size(); ++k) {
    if (!pinned.steps[k].odometry) continue;  // runMethod refuses such a log as it would the original
    pinned.steps[k].odometry = Odometry{motionBetween(trajectory[k - 1], trajectory[k]), pinnedCovariance(trajectory[k])};
  }
  return pinned;
}

std::vector<Pose> perturbedTrajectory(const std::vector<Pose>& trajectory, const std::vector<Matrix>& covariances,
                                      double scale, std::uint32_t seed) {
  if (!(scale >= 0.0) || !std::isfinite(scale)) throw std::invalid_argument("pose error scale must be finite and >= 0");
  if (scale == 0.0) return trajectory;
  if (covariances.size() != trajectory.size()) throw std::invalid_argument("perturbedTrajectory: one covariance per pose");
  std::mt19937 rng(seed);
  std::vector<Pose> moved;
  for (std::size_t k = 0; k < trajectory.size(); ++k) {
    const Vector delta = scale * sampleGaussian(Vector::Zero(tangentDimension(trajectory[k])), covariances[k], rng);
    moved.push_back(std::visit(
        [&](const auto& pose) -> Pose { return Manifold<std::decay_t<decltype(pose)>>::retract(pose, delta); },
        trajectory[k]));
  }
  return moved;
}

namespace {

/// Step 2's joint draw: the poses of X̂ ⊕ s δ, δ from the known-association posterior (PosteriorSampler.h).
std::vector<Pose> jointlyPerturbedTrajectory(const MethodRun& reference, double scale, std::uint32_t seed) {
  const PosteriorSampler sampler(reference.finalGraph, reference.finalEstimate);
  std::mt19937 rng(seed);
  const Values drawn = sampler.draw(scale, rng);
  std::vector<Pose> moved;
  for (std::size_t k = 0; k < reference.result.poses.size(); ++k) {
    moved.push_back(std::visit(
        [](const auto& value) -> Pose {
          using T = std::decay_t<decltype(value)>;
          if constexpr (std::is_same_v<T, SE2> || std::is_same_v<T, SE3>) return value;
          else throw std::logic_error("a pose key holds no pose");
        },
        drawn.value(poseKey(k))));
  }
  return moved;
}

}  // namespace

MethodRun runOnKnownTrajectory(const MeasurementLog& log, const MethodOptions& options, double poseErrorScale,
                               std::uint32_t seed, PoseErrorDraw draw) {
  if (!(poseErrorScale >= 0.0) || !std::isfinite(poseErrorScale)) {
    throw std::invalid_argument("pose error scale must be finite and >= 0");
  }
  if (isHybrid(options.method)) throw std::invalid_argument("the known-trajectory ceiling is for paper B's methods");
  MethodOptions known = options;
  known.method = Method::Known;
  // The options of the method under test that `known` refuses (it assigns nothing: no branches, no mixture to
  // switch) are that method's, not the reference's.
  known.switchRounds = 0;
  known.slam.loopClosureBranchWindow.reset();
  known.slam.loopClosureNextBest.reset();
  known.slam.loopClosureOpenSplits.reset();
  known.slam.assignmentScore.reset();
  const bool moved = poseErrorScale > 0.0;
  known.poseCovariances = moved && draw == PoseErrorDraw::Independent;
  known.keepFinalGraph = moved && draw == PoseErrorDraw::Joint;
  known.runFolder = false;
  const MethodRun reference = runMethod(log, known);
  const std::vector<Pose> trajectory =
      known.keepFinalGraph
          ? jointlyPerturbedTrajectory(reference, poseErrorScale, seed)
          : perturbedTrajectory(reference.result.poses, reference.result.poseCovariances, poseErrorScale, seed);
  MethodRun run = runMethod(logOnTrajectory(log, trajectory), options);
  run.result.method += "@known-trajectory";
  run.evaluation.metrics.method = run.result.method;
  run.settings["on_known_trajectory"] = {{"pose_error_scale", poseErrorScale},
                                         {"pose_error_draw", draw == PoseErrorDraw::Joint ? "joint" : "independent"},
                                         {"seed", seed}};
  return run;
}

}  // namespace semslam
