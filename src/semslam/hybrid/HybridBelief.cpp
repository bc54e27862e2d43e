#include "semslam/hybrid/HybridBelief.h"

#include <chrono>
#include <cmath>

#include "semslam/hybrid/Pruning.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

std::mt19937 runStream(std::uint64_t seed) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed & 0xffffffffu), static_cast<std::uint32_t>(seed >> 32),
                         0x4b1d0001u};
  return std::mt19937(sequence);
}

}  // namespace

HybridBelief::HybridBelief(const HybridProblem& problem, HybridOptions options)
    : problem_(problem), options_(std::move(options)), rng_(runStream(options_.seed)) {
  options_.validate();
  if (!options_.smootherFactory) options_.smootherFactory = defaultSmootherFactory();
  FactorGraph priors;
  Values values;
  problem_.priors(priors, values);
  std::unique_ptr<Smoother> smoother = options_.smootherFactory();
  smoother->update(priors, values);
  std::shared_ptr<const Smoother> shared = std::move(smoother);

  const int n = problem_.objects();
  if (!problem_.enumeratesClasses()) {
    components_.push_back({1.0, {}, {}, shared});
  } else if (!options_.enumerateAllClasses) {
    components_.push_back({1.0, {}, std::vector<int>(n, -1), shared});
  } else {
    const int m = problem_.classes();
    const double count = std::pow(static_cast<double>(m), n);
    if (count > 1e5) throw std::invalid_argument("hybrid: M^N class realizations are too many to enumerate");
    std::vector<int> classes(n, 0);
    for (long long r = 0; r < static_cast<long long>(count); ++r) {
      long long code = r;
      for (int j = 0; j < n; ++j) {
        classes[j] = static_cast<int>(code % m);
        code /= m;
      }
      components_.push_back({1.0 / count, {}, classes, shared});
    }
  }
}

std::size_t HybridBelief::heaviest() const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < components_.size(); ++i) {
    if (components_[i].weight > components_[best].weight) best = i;
  }
  return best;
}

HybridStepReport HybridBelief::update(const TimeStep& step) {
  const auto start = std::chrono::steady_clock::now();
  const int k = steps_;
  const Key pose = poseKey(static_cast<std::uint64_t>(k));
  HybridStepReport report;
  report.step = k;
  report.parents = components_.size();

  // 1. Propagate (Alg. 1 line 3): b⁻[X_k] = P(x_k | x_k−1, a_k−1) b[X_k−1] (A, eq. 11).
  std::vector<Key> jointKeys{pose};
  for (int j = 0; j < problem_.objects(); ++j) jointKeys.push_back(HybridProblem::objectKey(j));
  std::vector<PropagatedParent> parents(components_.size());
  for (std::size_t i = 0; i < components_.size(); ++i) {
    PropagatedParent& parent = parents[i];
    parent.component = &components_[i];
    if (k == 0) {
      parent.smoother = components_[i].smoother;
    } else {
      if (!step.odometry) throw InputError("hybrid belief: step " + std::to_string(k) + " has no odometry");
      std::unique_ptr<Smoother> propagated = components_[i].smoother->fork();
      const Key previous = poseKey(static_cast<std::uint64_t>(k - 1));
      FactorGraph motion;
      motion.add(problem_.factory().odometryFactor(previous, pose, *step.odometry));
      Values predicted;
      predicted.insert(pose, problem_.factory().predictPose(propagated->estimate().value(previous), *step.odometry));
      propagated->update(motion, predicted);
      parent.smoother = std::move(propagated);
    }
    parent.joint = parent.smoother->jointMarginal(jointKeys);  // marginalised to x_k and the objects (A, eq. 17)
  }

  // 2. PropWeights (lines 4-5): the children's weights (A, eq. 15-17).
  std::vector<AssociationCandidate> candidates =
      propagateWeights(problem_, options_, parents, k, step.detections, rng_, report.weights);

  // 3. PruneAndNormalize (line 7).
  std::vector<double> logWeights;
  for (const AssociationCandidate& c : candidates) logWeights.push_back(c.logWeight);
  const PruningResult pruned = pruneAndNormalize(logWeights, options_.pruneRatio, options_.maxComponents);
  report.prunedMass = pruned.prunedMass;
  report.cappedComponents = pruned.capped;

  // 4. Observation update of the survivors (lines 9-11): b[X_k] ∝ P(Z_k | X_k, C, β_k) b⁻[X_k] (A, eq. 9-10).
  std::vector<HybridComponent> next;
  for (std::size_t s = 0; s < pruned.kept.size(); ++s) {
    const AssociationCandidate& c = candidates[pruned.kept[s]];
    const PropagatedParent& parent = parents[c.parent];
    HybridComponent child;
    child.weight = pruned.weights[s];
    child.history = parent.component->history;
    child.history.push_back(c.beta);
    child.classes = c.classes;
    if (c.factors.empty()) {
      child.smoother = parent.smoother;
    } else {
      std::unique_ptr<Smoother> updated = parent.smoother->fork();
      updated->update(FactorGraph(c.factors));
      child.smoother = std::move(updated);
    }
    next.push_back(std::move(child));
  }
  components_ = std::move(next);
  report.survivors = components_.size();
  ++steps_;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace semslam
