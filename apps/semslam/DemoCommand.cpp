// semslam demo: the main job on its built-in default. For now, a simulated 2D pose graph with landmarks (a robot
// driving two laps of a rectangle among 16 landmarks, with noisy odometry and relative landmark observations),
// optimised by Gauss-Newton from dead reckoning; it prints the errors against the truth and writes the graph and
// a run folder (io/RunFolder.h) that python/plot_run.py draws.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <random>

#include "Commands.h"
#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/RunFolder.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/Optimizer.h"

namespace semslam::cli {

namespace {

struct DemoOptions {
  std::string out = "demo";
  unsigned seed = 1;
};

struct Truth {
  std::vector<SE2> poses;
  std::vector<Point2> landmarks;
};

/// Two laps of a 20 m × 10 m rectangle, one pose per metre, with 16 landmarks along its sides.
Truth makeTruth() {
  Truth truth;
  SE2 pose(0.0, 0.0, 0.0);
  for (int lap = 0; lap < 2; ++lap) {
    for (double side : {20.0, 10.0, 20.0, 10.0}) {
      for (int step = 0; step < static_cast<int>(side); ++step) {
        truth.poses.push_back(pose);
        const bool corner = step == static_cast<int>(side) - 1;
        pose = pose * SE2(1.0, 0.0, corner ? std::numbers::pi / 2 : 0.0);
      }
    }
  }
  truth.poses.push_back(pose);
  for (int i = 0; i < 6; ++i) {
    truth.landmarks.emplace_back(2.0 + 3.5 * i, -2.5);
    truth.landmarks.emplace_back(2.0 + 3.5 * i, 12.5);
  }
  for (double y : {2.5, 7.5}) {
    truth.landmarks.emplace_back(-2.5, y);
    truth.landmarks.emplace_back(22.5, y);
  }
  return truth;
}

double positionRmse(const Values& values, const Truth& truth) {
  double sum = 0.0;
  for (std::size_t i = 0; i < truth.poses.size(); ++i) {
    sum += (values.at<SE2>(i).translation() - truth.poses[i].translation()).squaredNorm();
  }
  return std::sqrt(sum / truth.poses.size());
}

/// The run folder: estimated and true trajectories, landmarks, and marginal position covariances.
RunOutput makeRunOutput(const FactorGraph& graph, const Values& estimate, const Truth& truth) {
  RunOutput run;
  std::vector<double> times;
  std::vector<SE3> estimated, trueSE3;
  for (std::size_t i = 0; i < truth.poses.size(); ++i) {
    times.push_back(static_cast<double>(i));
    estimated.push_back(toSE3(estimate.at<SE2>(i)));
    trueSE3.push_back(toSE3(truth.poses[i]));
  }
  run.trajectory = Trajectory(times, estimated);
  run.truth = Trajectory(times, trueSE3);
  const Marginals marginals(graph, estimate);
  for (std::size_t i = 0; i < truth.poses.size(); ++i) {
    run.posePositionCovariances.push_back(marginals.marginalCovariance(i).topLeftCorner(2, 2));
  }
  const std::size_t firstLandmark = truth.poses.size();
  for (std::size_t l = 0; l < truth.landmarks.size(); ++l) {
    const Key key = firstLandmark + l;
    run.landmarkTruth.push_back({static_cast<int>(l), -1, truth.landmarks[l]});
    if (!estimate.exists(key)) continue;
    run.landmarks.push_back({static_cast<int>(l), estimate.at<Point2>(key), -1, 0.0, marginals.marginalCovariance(key)});
  }
  return run;
}

void run(const DemoOptions& options) {
  const Truth truth = makeTruth();
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const Vector3 odometrySigmas(0.05, 0.05, 0.01);
  const Vector2 observationSigmas(0.1, 0.1);
  const double sensorRange = 6.0;
  const SharedNoiseModel odometryNoise = NoiseModel::fromSigmas(odometrySigmas);
  const SharedNoiseModel observationNoise = NoiseModel::fromSigmas(observationSigmas);

  // Keys: poses 0..N-1, landmarks after them (one id space, so the graph can be written as g2o).
  const std::size_t firstLandmark = truth.poses.size();
  FactorGraph graph;
  Values initial;
  graph.emplace<PriorFactor<SE2>>(0, truth.poses[0], NoiseModel::fromSigmas(Vector3(1e-3, 1e-3, 1e-4)));
  initial.insert(0, truth.poses[0]);
  std::size_t observations = 0;
  for (std::size_t i = 0; i < truth.poses.size(); ++i) {
    if (i > 0) {
      const SE2 odometry = truth.poses[i - 1].between(truth.poses[i]) *
                           SE2::Exp(odometrySigmas.cwiseProduct(Vector3(normal(rng), normal(rng), normal(rng))));
      graph.emplace<BetweenFactor<SE2>>(i - 1, i, odometry, odometryNoise);
      initial.insert(i, initial.at<SE2>(i - 1) * odometry);  // dead reckoning
    }
    for (std::size_t l = 0; l < truth.landmarks.size(); ++l) {
      const Point2 local = truth.poses[i].transformTo(truth.landmarks[l]);
      if (local.norm() > sensorRange) continue;
      const Point2 measured = local + observationSigmas.cwiseProduct(Vector2(normal(rng), normal(rng)));
      const Key landmark = firstLandmark + l;
      graph.emplace<RelativePointFactor<SE2, Point2>>(i, landmark, measured, observationNoise);
      if (!initial.exists(landmark)) initial.insert(landmark, initial.at<SE2>(i).transformFrom(measured));
      ++observations;
    }
  }
  std::printf("demo: %zu poses, %zu landmarks, %zu landmark observations, seed %u\n", truth.poses.size(),
              truth.landmarks.size(), observations, options.seed);

  const OptimizationResult result = optimize(graph, initial);
  std::printf("Gauss-Newton: chi2 %.6g -> %.6g in %d iterations (%s)\n", result.initialChi2, result.finalChi2,
              result.iterations, result.stopReason.c_str());
  std::printf("pose position RMSE against the truth: dead reckoning %.3f m, optimised %.3f m\n",
              positionRmse(initial, truth), positionRmse(result.values, truth));
  const Key last = truth.poses.size() - 1;
  const Matrix covariance = Marginals(graph, result.values).marginalCovariance(last);
  std::printf("last pose: estimate (%.3f, %.3f, %.3f), truth (%.3f, %.3f, %.3f), sigmas (%.3f m, %.3f m, %.4f rad)\n",
              result.values.at<SE2>(last).x(), result.values.at<SE2>(last).y(),
              result.values.at<SE2>(last).theta(), truth.poses.back().x(), truth.poses.back().y(),
              truth.poses.back().theta(), std::sqrt(covariance(0, 0)), std::sqrt(covariance(1, 1)),
              std::sqrt(covariance(2, 2)));

  std::filesystem::create_directories(options.out);
  const std::string path = (std::filesystem::path(options.out) / "optimized.g2o").string();
  writeG2o(path, graph, result.values);
  writeRunFolder(options.out, makeRunOutput(graph, result.values, truth));
  std::printf("wrote %s and the run folder %s\n", path.c_str(), options.out.c_str());
}

}  // namespace

void addDemoCommand(CLI::App& app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* command = app.add_subcommand("demo", "Run the main job on its built-in default scenario");
  command->add_option("--out", options->out, "output folder")->capture_default_str();
  command->add_option("--seed", options->seed, "random seed")->capture_default_str();
  command->callback([options]() { run(*options); });
}

}  // namespace semslam::cli
