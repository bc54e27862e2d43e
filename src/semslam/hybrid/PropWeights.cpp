#include "semslam/hybrid/PropWeights.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <tuple>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/ImportanceSampledLikelihood.h"
#include "semslam/association/LikelihoodTerms.h"
#include "semslam/association/MarginalLikelihood.h"
#include "semslam/hybrid/Pruning.h"

namespace semslam {
namespace {

constexpr double kNegativeInfinity = -std::numeric_limits<double>::infinity();

/// Per parent: the factors of (detection, object, class), built once and shared by every candidate using them.
class FactorCache {
 public:
  FactorCache(const HybridProblem& problem, int k, const std::vector<Detection>& detections)
      : problem_(problem), pose_(poseKey(static_cast<std::uint64_t>(k))), detections_(detections) {}

  const std::vector<FactorPtr>& get(int detection, int object, int classIndex) {
    const auto key = std::make_tuple(detection, object, classIndex);
    auto it = cache_.find(key);
    if (it == cache_.end()) {
      it = cache_.emplace(key, problem_.detectionFactors(pose_, object, detections_[detection], classIndex)).first;
    }
    return it->second;
  }

  const FactorPtr& gate(int detection, int object) {
    const auto key = std::make_pair(detection, object);
    auto it = gates_.find(key);
    if (it == gates_.end()) it = gates_.emplace(key, problem_.gateFactor(pose_, object, detections_[detection])).first;
    return it->second;
  }

 private:
  const HybridProblem& problem_;
  Key pose_;
  const std::vector<Detection>& detections_;
  std::map<std::tuple<int, int, int>, std::vector<FactorPtr>> cache_;
  std::map<std::pair<int, int>, FactorPtr> gates_;
};

/// The class whose factors detection i's object carries in `candidate` (0 without class enumeration).
int classOf(const HybridProblem& problem, const AssociationCandidate& candidate, int object) {
  return problem.enumeratesClasses() ? candidate.classes[object] : 0;
}

/// One parent's shared draws of x_k and the objects its candidates associate, with the per-draw log terms of every
/// (detection, object, class) factor set and of every object's visibility, each computed once: a candidate's terms
/// are their sum (sampledLogTerms adds over independent factor sets on the same draws), so the cost grows with the
/// distinct factor sets, not with the candidates. The visibility indicator of paper A factors over the associated
/// objects, P(β_k | X_s) = Π_i 1[β_{k,i} visible from x_s] (VisibilityModel2::associationFeasible; the objects of a
/// candidate are distinct by construction), so its log is the sum of per-object terms 0 or −∞.
class SharedDraws {
 public:
  SharedDraws(const HybridProblem& problem, const PropagatedParent& parent, const std::vector<Key>& keys,
              int samples, bool visibility, std::mt19937& rng)
      : problem_(problem),
        draws_(parent.smoother->estimate(), parent.joint.restrictedTo(keys), samples, rng),
        pose_(keys.front()),
        visibility_(visibility) {}

  /// log P(Z_k | X_s) + log P(β_k | X_s) of `candidate` at every draw s (A, eq. 16), its factors from `factors`.
  Vector logTerms(const AssociationCandidate& candidate, FactorCache& factors) {
    Vector sum = Vector::Zero(draws_.size());
    for (int i = 0; i < static_cast<int>(candidate.beta.size()); ++i) {
      const int object = candidate.beta[i];
      if (object < 0) continue;
      sum += factorTerms(i, object, classOf(problem_, candidate, object), factors);
      if (visibility_) sum += visibilityTerms(object);
    }
    return sum;
  }

 private:
  const Vector& factorTerms(int detection, int object, int classIndex, FactorCache& factors) {
    const auto key = std::make_tuple(detection, object, classIndex);
    auto it = factorTerms_.find(key);
    if (it == factorTerms_.end()) {
      it = factorTerms_.emplace(key, sampledLogTerms(factors.get(detection, object, classIndex), draws_)).first;
    }
    return it->second;
  }

  const Vector& visibilityTerms(int object) {
    auto it = visibilityTerms_.find(object);
    if (it != visibilityTerms_.end()) return it->second;
    Vector terms(draws_.size());
    const Key objectKey = HybridProblem::objectKey(object);
    for (int s = 0; s < draws_.size(); ++s) {
      const Vector p = MeasurementFactory::positionOf(draws_.draw(objectKey, s));
      terms(s) = problem_.visible(draws_.draw(pose_, s), p) ? 0.0 : kNegativeInfinity;
    }
    return visibilityTerms_.emplace(object, std::move(terms)).first->second;
  }

  const HybridProblem& problem_;
  MarginalSamples draws_;
  Key pose_;
  bool visibility_;
  std::map<std::tuple<int, int, int>, Vector> factorTerms_;
  std::map<int, Vector> visibilityTerms_;
};

/// The keys of a candidate's integral: x_k, then its objects in order of first association.
std::vector<Key> integralKeys(Key pose, const std::vector<int>& beta) {
  std::vector<Key> keys{pose};
  for (int object : beta) {
    if (object >= 0) keys.push_back(HybridProblem::objectKey(object));
  }
  return keys;
}

/// Appends detection i → object (with class c when semantic) to a partial candidate.
AssociationCandidate extend(const AssociationCandidate& partial, const HybridProblem& problem, FactorCache& cache,
                            const Detection& detection, int i, int object, int classIndex, bool newObject) {
  AssociationCandidate child = partial;
  child.beta.push_back(object);
  const std::vector<FactorPtr>& factors = cache.get(i, object, classIndex);
  child.factors.insert(child.factors.end(), factors.begin(), factors.end());  // P(z_geo) · P(z_sem) (A, eq. 10)
  child.gateFactors.push_back(cache.gate(i, object));
  child.analyticFactors.push_back(child.gateFactors.back());
  child.analyticFactors.insert(child.analyticFactors.end(), factors.begin() + 1, factors.end());  // semantic part
  if (problem.enumeratesClasses()) {
    child.logConstant += problem.semanticLogConstant(detection, classIndex);
    if (newObject) {
      child.classes[object] = classIndex;
      child.logConstant -= std::log(static_cast<double>(problem.classes()));  // class prior P(c) = 1/M (A, eq. 3)
    }
  }
  return child;
}

/// The class choices for associating `object` in `partial`: its class if known, else every class.
std::vector<int> classChoices(const HybridProblem& problem, const AssociationCandidate& partial, int object) {
  if (!problem.enumeratesClasses()) return {0};
  if (partial.classes[object] >= 0) return {partial.classes[object]};
  std::vector<int> all(problem.classes());
  for (int c = 0; c < problem.classes(); ++c) all[c] = c;
  return all;
}

bool uses(const std::vector<int>& beta, int object) { return std::find(beta.begin(), beta.end(), object) != beta.end(); }

/// Calls `visit` with every one-detection extension of `partial` (A sec. III: β_k assigns the step's detections to
/// distinct objects): detection i → each object that `partial` does not use yet, with each of its class choices,
/// in order of object, then class.
template <class Visit>
void forEachExtension(const AssociationCandidate& partial, const HybridProblem& problem, FactorCache& cache,
                      const Detection& detection, int i, Visit&& visit) {
  for (int object = 0; object < problem.objects(); ++object) {
    if (uses(partial.beta, object)) continue;
    const bool isNew = problem.enumeratesClasses() && partial.classes[object] < 0;
    for (int c : classChoices(problem, partial, object)) {
      visit(extend(partial, problem, cache, detection, i, object, c, isNew));
    }
  }
}

void linearize(AssociationCandidate& candidate, const PropagatedParent& parent, Key pose) {
  // w_β1:k−1 comes out of the integral (A, eq. 16).
  const double base = std::log(parent.component->weight) + candidate.logConstant;
  if (candidate.factors.empty()) {
    candidate.linearizedLogWeight = candidate.gateLogWeight = base;
    candidate.innovationChi2 = 0.0;
    return;
  }
  const JointMarginal marginal = parent.joint.restrictedTo(integralKeys(pose, candidate.beta));  // (A, eq. 17)
  const Values& estimate = parent.smoother->estimate();
  const LinearizedLikelihood gate = linearizedLikelihood(candidate.gateFactors, estimate, marginal);
  candidate.gateLogWeight = base + gate.logLikelihood;
  candidate.innovationChi2 = gate.innovationChi2;
  if (candidate.analyticFactors.size() == candidate.gateFactors.size()) {
    candidate.linearizedLogWeight = candidate.gateLogWeight;
  } else {
    candidate.linearizedLogWeight =
        base + linearizedLikelihood(candidate.analyticFactors, estimate, marginal).logLikelihood;
  }
}

AssociationCandidate root(const PropagatedParent& parent, std::size_t index) {
  AssociationCandidate candidate;
  candidate.parent = index;
  candidate.classes = parent.component->classes;
  return candidate;
}

/// The upper bound of whole-association candidates: Σ_parents N!/(N−n)! · M^n (M = 1 without class enumeration), in
/// floating point so that it cannot overflow.
double wholeAssociationBound(const HybridProblem& problem, std::size_t parents, std::size_t detections) {
  double perParent = 1.0;
  for (std::size_t i = 0; i < detections; ++i) {
    perParent *= std::max(0.0, static_cast<double>(problem.objects()) - static_cast<double>(i));
    if (problem.enumeratesClasses()) perParent *= problem.classes();
  }
  return perParent * static_cast<double>(parents);
}

/// Keeps the `cap` heaviest of `candidates` by gate weight (earlier first among ties), in their order.
std::size_t keepHeaviest(std::vector<AssociationCandidate>& candidates, std::size_t cap) {
  if (candidates.size() <= cap) return 0;
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return candidates[a].gateLogWeight > candidates[b].gateLogWeight;
  });
  order.resize(cap);
  std::sort(order.begin(), order.end());
  std::vector<AssociationCandidate> kept;
  kept.reserve(cap);
  for (std::size_t i : order) kept.push_back(std::move(candidates[i]));
  const std::size_t dropped = candidates.size() - cap;
  candidates = std::move(kept);
  return dropped;
}

std::vector<AssociationCandidate> wholeAssociations(const HybridProblem& problem,
                                                    const std::vector<PropagatedParent>& parents, int k,
                                                    const std::vector<Detection>& detections,
                                                    std::vector<FactorCache>& caches) {
  const Key pose = poseKey(static_cast<std::uint64_t>(k));
  std::vector<AssociationCandidate> all;
  for (std::size_t p = 0; p < parents.size(); ++p) {
    std::vector<AssociationCandidate> partials{root(parents[p], p)};
    for (int i = 0; i < static_cast<int>(detections.size()); ++i) {
      std::vector<AssociationCandidate> next;
      for (const AssociationCandidate& partial : partials) {
        forEachExtension(partial, problem, caches[p], detections[i], i,
                         [&](AssociationCandidate child) { next.push_back(std::move(child)); });
      }
      partials = std::move(next);
    }
    for (AssociationCandidate& candidate : partials) {
      linearize(candidate, parents[p], pose);
      all.push_back(std::move(candidate));
    }
  }
  return all;
}

std::vector<AssociationCandidate> oneDetectionAtATime(const HybridProblem& problem, const HybridOptions& options,
                                                      const std::vector<PropagatedParent>& parents, int k,
                                                      const std::vector<Detection>& detections,
                                                      std::vector<FactorCache>& caches, PropWeightsReport& report) {
  const Key pose = poseKey(static_cast<std::uint64_t>(k));
  const AssociationGate compatibility(options.jointCompatibility);
  const std::size_t candidateCap = static_cast<std::size_t>(options.maxCandidates);
  std::vector<AssociationCandidate> partials;
  for (std::size_t p = 0; p < parents.size(); ++p) {
    partials.push_back(root(parents[p], p));
    linearize(partials.back(), parents[p], pose);
  }
  for (int i = 0; i < static_cast<int>(detections.size()); ++i) {
    std::vector<AssociationCandidate> next;
    for (const AssociationCandidate& partial : partials) {
      forEachExtension(partial, problem, caches[partial.parent], detections[i], i, [&](AssociationCandidate child) {
        linearize(child, parents[partial.parent], pose);
        int dimension = 0;
        for (const FactorPtr& f : child.gateFactors) dimension += f->errorDimension();
        // Joint compatibility: the stacked innovation passes the χ² test at its dimension.
        if (child.innovationChi2 <= compatibility.threshold(dimension)) next.push_back(std::move(child));
        if (next.size() >= 2 * candidateCap) report.truncatedPartials += keepHeaviest(next, candidateCap);
      });
    }
    report.truncatedPartials += keepHeaviest(next, candidateCap);
    if (next.empty()) {  // no partial association can take detection i: drop it everywhere
      ++report.droppedDetections;
      for (AssociationCandidate& partial : partials) partial.beta.push_back(-1);
      continue;
    }
    // Prune partial hypotheses by linearised weight (the gate's ratio) and, with a component cap, keep at most
    // ten times the cap.
    std::vector<double> logWeights;
    for (const AssociationCandidate& c : next) logWeights.push_back(c.gateLogWeight);
    const int cap = options.maxComponents > 0 ? 10 * options.maxComponents : 0;
    const PruningResult kept = pruneAndNormalize(logWeights, options.gateRatio, cap);
    partials.clear();
    for (std::size_t index : kept.kept) partials.push_back(std::move(next[index]));
  }
  return partials;
}

}  // namespace

std::vector<AssociationCandidate> propagateWeights(const HybridProblem& problem, const HybridOptions& options,
                                                   const std::vector<PropagatedParent>& parents, int k,
                                                   const std::vector<Detection>& detections, std::mt19937& rng,
                                                   PropWeightsReport& report) {
  bool whole = options.branching == Branching::WholeAssociation;
  if (whole) {
    report.wholeAssociationBound = wholeAssociationBound(problem, parents.size(), detections.size());
    report.branchedOneAtATime = report.wholeAssociationBound > static_cast<double>(options.maxCandidates);
    whole = !report.branchedOneAtATime;
  }
  std::vector<FactorCache> caches;  // per parent: the factors every candidate of that parent shares
  for (std::size_t p = 0; p < parents.size(); ++p) caches.emplace_back(problem, k, detections);
  std::vector<AssociationCandidate> candidates =
      whole ? wholeAssociations(problem, parents, k, detections, caches)
            : oneDetectionAtATime(problem, options, parents, k, detections, caches, report);
  report.candidates = candidates.size();
  if (candidates.empty()) return candidates;

  // Gate on the linearised weights.
  double maximumGate = kNegativeInfinity;
  for (const AssociationCandidate& c : candidates) maximumGate = std::max(maximumGate, c.gateLogWeight);
  const double gateLevel = options.gateRatio > 1.0 ? maximumGate - std::log(options.gateRatio) : kNegativeInfinity;
  double total = 0.0, lost = 0.0;
  for (AssociationCandidate& c : candidates) {
    const double w = std::isfinite(maximumGate) ? std::exp(c.gateLogWeight - maximumGate) : 0.0;
    total += w;
    c.gated = c.gateLogWeight < gateLevel;
    if (c.gated) {
      lost += w;
      ++report.gated;
    }
  }
  report.gateLostMass = total > 0.0 ? lost / total : 0.0;

  const Key pose = poseKey(static_cast<std::uint64_t>(k));
  const auto start = std::chrono::steady_clock::now();
  // Plain Monte Carlo draws x_k and the objects the parent's surviving candidates associate once per parent (one
  // Cholesky of their joint marginal, eq. 17) and weighs every candidate of that parent on those draws (common
  // random numbers), each factor set once (SharedDraws). Candidates come grouped by parent, so one parent's draws
  // are held at a time.
  const auto sampled = [&](const AssociationCandidate& c) {
    return !c.gated && options.weights != WeightMethod::Analytic && !c.factors.empty();
  };
  std::optional<SharedDraws> draws;
  std::size_t drawsParent = 0;
  std::vector<Vector> visibilityPositions;  // the importance path's per-sample buffers
  std::vector<int> visibilityBeta;
  bool anyPositive = false;
  for (std::size_t index = 0; index < candidates.size(); ++index) {
    AssociationCandidate& c = candidates[index];
    if (c.gated) {
      c.logWeight = kNegativeInfinity;
      continue;
    }
    if (!sampled(c)) {
      c.logWeight = c.linearizedLogWeight;
      if (std::isfinite(c.logWeight)) anyPositive = true;
      continue;
    }
    const PropagatedParent& parent = parents[c.parent];
    SampledLikelihood likelihood;
    if (options.weights == WeightMethod::Importance) {
      const std::vector<Key> keys = integralKeys(pose, c.beta);
      SampleWeight visibility;
      if (options.visibility) {  // the object observation model P(β_k | x_k, X^o_β) (A, eq. 14, 16)
        visibility = [&](const Values& sample) {
          visibilityPositions.clear();
          visibilityBeta.clear();
          for (std::size_t i = 1; i < keys.size(); ++i) {
            visibilityPositions.push_back(MeasurementFactory::positionOf(sample.value(keys[i])));
            visibilityBeta.push_back(static_cast<int>(i - 1));
          }
          return problem.associationFeasible(sample.value(keys[0]), visibilityPositions,
                                                          visibilityBeta)
                     ? 1.0
                     : 0.0;
        };
      }
      const JointMarginal marginal = parent.joint.restrictedTo(keys);  // b⁻[x_k, X^o_β] (A, eq. 17)
      likelihood = importanceSampledLikelihood(c.factors, parent.smoother->estimate(), marginal, options.samples,
                                               rng, visibility, ImportanceProposal{options.importanceIterations});
    } else {
      if (!draws || drawsParent != c.parent) {
        // x_k and every object a surviving candidate of this parent associates, in key order: b⁻[x_k, X^o_used]
        std::vector<bool> used(static_cast<std::size_t>(problem.objects()), false);
        for (std::size_t j = index; j < candidates.size() && candidates[j].parent == c.parent; ++j) {
          if (!sampled(candidates[j])) continue;
          for (int object : candidates[j].beta) {
            if (object >= 0) used[static_cast<std::size_t>(object)] = true;
          }
        }
        std::vector<Key> keys{pose};
        for (int object = 0; object < problem.objects(); ++object) {
          if (used[static_cast<std::size_t>(object)]) keys.push_back(HybridProblem::objectKey(object));
        }
        draws.emplace(problem, parent, keys, options.samples, options.visibility, rng);
        drawsParent = c.parent;
      }
      likelihood = meanOfExponentials(draws->logTerms(c, caches[c.parent]));
    }
    // w_β1:k ∝ w_β1:k−1 · (1/n_s) Σ_s P(Z_k | X_s) P(β_k | X_s) (A, eq. 16-17)
    c.logWeight = std::log(parent.component->weight) + likelihood.logLikelihood + c.logConstant;
    c.relativeStandardError = likelihood.relativeStandardError;
    ++report.sampled;
    if (std::isfinite(c.logWeight)) anyPositive = true;
  }
  report.samplingSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!anyPositive) {
    report.fellBackToLinearized = true;
    for (AssociationCandidate& c : candidates) c.logWeight = c.gated ? kNegativeInfinity : c.linearizedLogWeight;
  }

  // Agreement of the sampled weights with the linearised ones, over the candidates that were sampled.
  if (options.weights != WeightMethod::Analytic && report.sampled > 0 && !report.fellBackToLinearized) {
    std::vector<double> sampled, linear;
    for (const AssociationCandidate& c : candidates) {
      if (c.gated) continue;
      sampled.push_back(c.logWeight);
      linear.push_back(c.linearizedLogWeight);
    }
    const std::vector<double> ws = normalizeLogWeights(sampled), wl = normalizeLogWeights(linear);
    double distance = 0.0;
    for (std::size_t i = 0; i < ws.size(); ++i) distance += std::abs(ws[i] - wl[i]);
    report.analyticTotalVariation = 0.5 * distance;
    std::size_t index = 0;
    for (const AssociationCandidate& c : candidates) {
      if (c.gated) continue;
      if (ws[index++] >= 1e-3) report.maxRelativeStandardError = std::max(report.maxRelativeStandardError, c.relativeStandardError);
    }
  }
  return candidates;
}

}  // namespace semslam
