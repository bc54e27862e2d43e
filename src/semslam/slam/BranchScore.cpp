#include "semslam/slam/BranchScore.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "semslam/factors/MaxMixtureFactor.h"
#include "semslam/solve/LaplaceEvidence.h"
#include "semslam/solve/Optimizer.h"

namespace semslam {
namespace {

/// ln of a label likelihood vector's entries, a zero likelihood as the smallest positive double (a label that
/// rules a class out leaves that class a vanishing but finite weight).
Vector logOf(const Vector& likelihoods) {
  return likelihoods.array().max(std::numeric_limits<double>::min()).log().matrix();
}

/// −2 ln of the labels' evidence (the last two lines of the header's formula).
double labelScore(const SemanticSlam& run, const Values& estimate) {
  double logEvidence = 0.0;
  std::map<int, Vector> logProducts;  // per landmark: ln Π_r P(s_r | c), per class
  for (const DetectionRecord& record : run.detections()) {
    if (record.semanticLikelihoods.size() == 0) continue;  // no label
    const std::optional<int> landmark = run.chosenAssociation(record, estimate).first;
    if (!landmark) {
      logEvidence += std::log(std::max(record.semanticLikelihoods.mean(), std::numeric_limits<double>::min()));
      continue;
    }
    auto [entry, inserted] = logProducts.try_emplace(*landmark, Vector::Zero(record.semanticLikelihoods.size()));
    entry->second += logOf(record.semanticLikelihoods);
  }
  for (const auto& [landmark, logProduct] : logProducts) {  // ln Σ_c (1/M) exp(ln Π), by log-sum-exp
    const double top = logProduct.maxCoeff();
    logEvidence += top + std::log((logProduct.array() - top).exp().sum() / static_cast<double>(logProduct.size()));
  }
  return -2.0 * logEvidence;
}

/// −2 ln of the unassigned density λ(z) of every detection on no factor: under §1's model a detection that no
/// landmark explains comes from the unassigned density (its label's P₀ is in labelScore).
double unexplainedScore(const SemanticSlam& run, const UnassignedHypothesis& unassigned) {
  double score = 0.0;
  for (const DetectionRecord& record : run.detections()) {
    if (record.onNoFactor()) score -= 2.0 * unassigned.logDensity(record.measurement);
  }
  return score;
}

}  // namespace

double branchScore(const SemanticSlam& run) { return branchScore(run, run.unassignedHypothesis().rate()); }

double branchScore(const SemanticSlam& run, double unassignedRate) {
  const UnassignedHypothesis unassigned = run.unassignedHypothesis().withRate(unassignedRate);
  const FactorGraph factors = run.smoother().factors();
  OptimizerParams params;
  params.chi2DecreaseTolerance = kBranchScoreTolerance;
  const Values estimate = optimize(factors, run.smoother().estimate(), params).values;

  std::set<const Factor*> placeholders;
  for (FactorIndex index : run.weakPriors()) placeholders.insert(run.smoother().factor(index).get());
  FactorGraph model;
  for (const FactorPtr& factor : factors) {
    if (placeholders.contains(factor.get())) continue;
    if (const auto* mixture = dynamic_cast<const MaxMixtureFactor*>(factor.get())) {
      model.add(mixture->components()[static_cast<std::size_t>(mixture->activeComponent(estimate))].factor);
    } else {
      model.add(factor);
    }
  }
  int activeLandmarks = 0;
  for (int j = 0; j < run.landmarks(); ++j) activeLandmarks += run.lifecycle().active(j) ? 1 : 0;
  // Each active landmark's prior is ρ; an orientation prior's position part, in the model above, stands in for it
  // there and is taken out (an inactive landmark keeps it: with nothing else on its variable it integrates to 1).
  const double landmarkPrior =
      -2.0 * unassigned.logLandmarkDensity() - run.orientationPriorPositionScore().value_or(0.0);
  return laplaceEvidenceScore(model, estimate) + activeLandmarks * landmarkPrior + unexplainedScore(run, unassigned) +
         labelScore(run, estimate);
}

}  // namespace semslam
