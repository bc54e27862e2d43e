#include "semslam/io/PoseGraphReplay.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/io/PoseGraphAnchor.h"

namespace semslam {

namespace {

bool isPose(const Value& value) { return std::holds_alternative<SE2>(value) || std::holds_alternative<SE3>(value); }

/// If `factor` is a between factor joining `a` and `b`, the value of `b` chained from `a`'s value.
template <class T>
std::optional<Value> chainBetween(const Factor& factor, Key a, Key b, const Value& valueOfA) {
  const auto* between = dynamic_cast<const BetweenFactor<T>*>(&factor);
  if (between == nullptr || !std::holds_alternative<T>(valueOfA)) return std::nullopt;
  const T& xa = std::get<T>(valueOfA);
  if (factor.keys()[0] == a && factor.keys()[1] == b) return Value(xa * between->measured());
  if (factor.keys()[0] == b && factor.keys()[1] == a) return Value(xa * between->measured().inverse());
  return std::nullopt;
}

template <class Pose, class Point>
std::optional<Value> observe(const Factor& factor, Key landmark, const Values& current, const Values& fresh) {
  const auto* observation = dynamic_cast<const RelativePointFactor<Pose, Point>*>(&factor);
  if (observation == nullptr || factor.keys()[1] != landmark) return std::nullopt;
  const Key pose = factor.keys()[0];
  const Value& x = fresh.exists(pose) ? fresh.value(pose) : current.value(pose);
  if (!std::holds_alternative<Pose>(x)) return std::nullopt;
  return Value(Point(std::get<Pose>(x).transformFrom(observation->measured())));
}

}  // namespace

PoseGraphReplay::PoseGraphReplay(const PoseGraphFile& file) : fileValues_(file.initial) {
  graph_ = file.factors;
  graph_.add(anchorFactors(file));
  std::map<Key, int> poseStep;
  for (const auto& [key, value] : file.initial) {
    if (isPose(value)) poses_.push_back(key);
  }
  if (poses_.empty()) throw std::invalid_argument("PoseGraphReplay: the graph has no pose");
  for (std::size_t i = 0; i < poses_.size(); ++i) poseStep[poses_[i]] = static_cast<int>(i);

  // Latest pose step of each factor (−1: no pose), then the landmarks' entry steps.
  std::vector<int> latestPose(graph_.size(), -1);
  std::map<Key, int> landmarkStep;
  for (std::size_t f = 0; f < graph_.size(); ++f) {
    for (Key key : graph_[f]->keys()) {
      const auto it = poseStep.find(key);
      if (it != poseStep.end()) latestPose[f] = std::max(latestPose[f], it->second);
    }
    if (latestPose[f] < 0) continue;
    for (Key key : graph_[f]->keys()) {
      if (poseStep.count(key)) continue;
      const auto [it, inserted] = landmarkStep.emplace(key, latestPose[f]);
      if (!inserted) it->second = std::min(it->second, latestPose[f]);
    }
  }
  factorsOfStep_.resize(poses_.size());
  landmarksOfStep_.resize(poses_.size());
  for (std::size_t f = 0; f < graph_.size(); ++f) {
    int step = std::max(latestPose[f], 0);
    for (Key key : graph_[f]->keys()) {
      if (poseStep.count(key)) continue;
      const auto it = landmarkStep.find(key);
      const int entry = it == landmarkStep.end() ? 0 : it->second;
      if (it == landmarkStep.end()) landmarkStep.emplace(key, 0);
      step = std::max(step, entry);
    }
    factorsOfStep_[step].push_back(graph_[f]);
  }
  for (const auto& [key, step] : landmarkStep) landmarksOfStep_[step].push_back(key);
}

Value PoseGraphReplay::initialPose(std::size_t index, const Values& current, const Values& fresh) const {
  const Key pose = poses_[index];
  if (index == 0) return fileValues_.value(pose);
  const Key previous = poses_[index - 1];
  // The odometry edge first, then any edge to an earlier pose.
  for (int pass = 0; pass < 2; ++pass) {
    for (const auto& factor : factorsOfStep_[index]) {
      if (factor->keys().size() != 2) continue;
      const Key other = factor->keys()[0] == pose ? factor->keys()[1] : factor->keys()[0];
      if (other == pose || (factor->keys()[0] != pose && factor->keys()[1] != pose)) continue;
      if (pass == 0 && other != previous) continue;
      if (!current.exists(other) || fresh.exists(other)) continue;
      const Value& from = current.value(other);
      if (auto chained = chainBetween<SE2>(*factor, other, pose, from)) return *chained;
      if (auto chained = chainBetween<SE3>(*factor, other, pose, from)) return *chained;
    }
  }
  return fileValues_.value(pose);
}

Value PoseGraphReplay::initialLandmark(Key landmark, std::size_t index, const Values& current,
                                       const Values& fresh) const {
  for (const auto& factor : factorsOfStep_[index]) {
    if (auto observed = observe<SE2, Point2>(*factor, landmark, current, fresh)) return *observed;
    if (auto observed = observe<SE3, Point3>(*factor, landmark, current, fresh)) return *observed;
  }
  return fileValues_.value(landmark);
}

ReplayStep PoseGraphReplay::step(std::size_t index, const Values& current) const {
  if (index >= poses_.size()) throw std::out_of_range("PoseGraphReplay::step: no step " + std::to_string(index));
  ReplayStep step;
  step.pose = poses_[index];
  step.values.insert(step.pose, initialPose(index, current, step.values));
  for (Key landmark : landmarksOfStep_[index]) {
    step.values.insert(landmark, initialLandmark(landmark, index, current, step.values));
  }
  step.factors = FactorGraph(factorsOfStep_[index]);
  return step;
}

}  // namespace semslam
