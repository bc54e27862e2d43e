#pragma once
// Small seeded problems shared by the solver tests: a 2D trajectory with landmarks, and a linear point graph; a
// problem split into the steps an online front end would feed a smoother.

#include <random>
#include <set>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/graph/FactorGraph.h"

namespace semslam::test {

struct Problem {
  FactorGraph graph;
  Values initial;
};

/// A robot on a circle observing landmarks, with a prior on its first pose; initial values perturbed.
inline Problem planarSlamProblem(int poses = 12, int landmarks = 5, unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Problem problem;
  auto noise3 = NoiseModel::fromSigmas(Vector3(0.05, 0.05, 0.02));
  auto noise2 = NoiseModel::fromSigmas(Vector2(0.1, 0.1));
  std::vector<SE2> truth;
  for (int i = 0; i < poses; ++i) {
    const double angle = 2.0 * 3.14159265358979 * i / poses;
    truth.emplace_back(5.0 * std::cos(angle), 5.0 * std::sin(angle), angle + 1.5707963267949);
  }
  problem.graph.emplace<PriorFactor<SE2>>(poseKey(0), truth[0], NoiseModel::fromSigmas(Vector3(0.01, 0.01, 0.01)));
  for (int i = 0; i < poses; ++i) {
    const SE2 noisy = truth[i] * SE2::Exp(Vector3(0.2 * normal(rng), 0.2 * normal(rng), 0.05 * normal(rng)));
    problem.initial.insert(poseKey(i), noisy);
    if (i > 0) {
      const SE2 z = truth[i - 1].between(truth[i]) * SE2::Exp(Vector3(0.05 * normal(rng), 0.05 * normal(rng),
                                                                      0.02 * normal(rng)));
      problem.graph.emplace<BetweenFactor<SE2>>(poseKey(i - 1), poseKey(i), z, noise3);
    }
  }
  for (int l = 0; l < landmarks; ++l) {
    const double angle = 2.0 * 3.14159265358979 * l / landmarks;
    const Point2 landmark(7.0 * std::cos(angle), 7.0 * std::sin(angle));
    problem.initial.insert(landmarkKey(l), Point2(landmark + Point2(0.3 * normal(rng), 0.3 * normal(rng))));
    for (int i = 0; i < poses; ++i) {
      if ((truth[i].translation() - landmark).norm() > 6.0) continue;
      const Point2 z = truth[i].transformTo(landmark) + Point2(0.1 * normal(rng), 0.1 * normal(rng));
      problem.graph.emplace<RelativePointFactor<SE2, Point2>>(poseKey(i), landmarkKey(l), z, noise2);
    }
  }
  return problem;
}

/// A small problem fed pose by pose: pose i with every factor whose variables are poses ≤ i or landmarks, each
/// landmark entering with its first factor.
struct Steps {
  std::vector<FactorGraph> factors;
  std::vector<Values> values;
};

inline Steps splitByPose(const Problem& problem, int poses) {
  Steps steps;
  steps.factors.resize(poses);
  steps.values.resize(poses);
  std::set<Key> known;
  for (const auto& factor : problem.graph) {
    int step = 0;
    for (Key key : factor->keys()) {
      if (Symbol(key).tag() == 'x') step = std::max(step, static_cast<int>(Symbol(key).index()));
    }
    steps.factors[step].add(factor);
  }
  for (int i = 0; i < poses; ++i) {
    for (const auto& factor : steps.factors[i]) {
      for (Key key : factor->keys()) {
        if (known.insert(key).second) steps.values[i].insert(key, problem.initial.value(key));
      }
    }
  }
  return steps;
}

/// Largest tangent difference between two estimates over the keys of `b` (local coordinates of a in b's frame).
inline double maxDifference(const Values& a, const Values& b) {
  double worst = 0.0;
  for (const auto& [key, value] : b) {
    const Value& other = a.value(key);
    const Vector d = std::visit(
        [&](const auto& vb) -> Vector {
          using T = std::decay_t<decltype(vb)>;
          return Manifold<T>::local(vb, std::get<T>(other));
        },
        value);
    worst = std::max(worst, d.cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace semslam::test
