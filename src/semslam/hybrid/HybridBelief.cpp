#include "semslam/hybrid/HybridBelief.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "semslam/hybrid/Pruning.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

std::mt19937 runStream(std::uint64_t seed) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed & 0xffffffffu), static_cast<std::uint32_t>(seed >> 32),
                         0x4b1d0001u};
  return std::mt19937(sequence);
}

/// How many children the memory budget holds at step k (HybridOptions::maxMemoryMiB): each child will hold about
/// what its propagated parent holds now (its estimate and the factorization its joint marginal was read from),
/// and the previous components, their propagated copies and the children are alive at once. `componentBytes`
/// receives the largest parent's size. Throws std::runtime_error when not one component fits.
int componentsWithinMemory(const std::vector<PropagatedParent>& parents, double maxMemoryMiB, int k,
                           double& componentBytes) {
  std::size_t largest = 0;
  for (const PropagatedParent& parent : parents) largest = std::max(largest, parent.smoother->memoryBytes());
  componentBytes = static_cast<double>(largest);
  const double budget = maxMemoryMiB * 1024.0 * 1024.0;
  const double fits = std::floor(budget / (3.0 * std::max(componentBytes, 1.0)));
  if (fits < 1.0) {
    char sizes[160];
    std::snprintf(sizes, sizeof sizes, "one component's smoother holds %.3g MiB and a step holds three copies, more "
                  "than --max-memory %.6g MiB", componentBytes / (1024.0 * 1024.0), maxMemoryMiB);
    throw std::runtime_error("hybrid belief, step " + std::to_string(k) + ": " + sizes +
                             "; raise --max-memory (docs/hybrid-belief.md, \"Bounded memory\")");
  }
  return static_cast<int>(std::min(fits, 1e9));
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
    components_.push_back({1.0, {}, -1, {}, shared});
  } else if (!options_.enumerateAllClasses) {
    components_.push_back({1.0, {}, -1, std::vector<int>(n, -1), shared});
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
      components_.push_back({1.0 / count, {}, -1, classes, shared});
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
  const int memoryCap = componentsWithinMemory(parents, options_.maxMemoryMiB, k, report.componentBytes);
  const int cap = options_.maxComponents > 0 ? std::min(options_.maxComponents, memoryCap) : memoryCap;
  const PruningResult pruned = pruneAndNormalize(logWeights, options_.pruneRatio, cap);
  report.prunedMass = pruned.prunedMass;
  report.cappedComponents = pruned.capped;
  const std::size_t passedRatio = pruned.kept.size() + pruned.capped;
  const std::size_t countCapped = options_.maxComponents > 0 && passedRatio > std::size_t(options_.maxComponents)
                                      ? passedRatio - static_cast<std::size_t>(options_.maxComponents)
                                      : 0;
  report.memoryCappedComponents = pruned.capped - countCapped;

  // 4. Observation update of the survivors (lines 9-11): b[X_k] ∝ P(Z_k | X_k, C, β_k) b⁻[X_k] (A, eq. 9-10).
  std::vector<HybridComponent> next;
  HistoryInterner histories;  // children with equal histories share them (class realizations of one β_1:k)
  for (std::size_t s = 0; s < pruned.kept.size(); ++s) {
    const AssociationCandidate& c = candidates[pruned.kept[s]];
    const PropagatedParent& parent = parents[c.parent];
    HybridComponent child;
    child.weight = pruned.weights[s];
    std::vector<int> ids;
    for (int object : c.beta) ids.push_back(object >= 0 ? problem_.objectId(object) : -1);
    child.history = histories.extend(parent.component->history, ids);
    child.ancestor = k == 0 ? -1 : static_cast<int>(c.parent);  // the prior's components are no step
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
