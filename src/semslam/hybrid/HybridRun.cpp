#include "semslam/hybrid/HybridRun.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "semslam/models/ValueConversions.h"

namespace semslam {

HybridRunOutput runHybrid(const MeasurementLog& log, const HybridOptions& options, const HybridProgress& progress,
                          const HybridStepObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  const HybridProblem problem(log.header, options.useSemantics);
  HybridBelief belief(problem, options);
  HybridRunOutput out;
  const int steps = static_cast<int>(log.steps.size());
  std::chrono::steady_clock::duration observing{};  // the observer's time is not the estimator's
  for (int k = 0; k < steps; ++k) {
    HybridStepRecord record;
    record.report = belief.update(log.steps[k]);
    record.marginals = hybridMarginals(belief);
    out.result.heaviestAssociationWeights.push_back(record.marginals.association.front().weight);  // max_β P(β | H_k)
    out.reports.push_back(record.report);
    if (observer) {
      const auto before = std::chrono::steady_clock::now();
      observer(record);
      observing += std::chrono::steady_clock::now() - before;
    }
    if (k + 1 == steps) out.finalMarginals = std::move(record.marginals);
    if (progress) progress(k + 1, steps);
  }

  RunResult& result = out.result;
  result.method = options.useSemantics ? "hybrid" : "hybrid-geometric";
  if (steps > 0) {
    const HybridComponent& best = belief.components()[belief.heaviest()];
    const Smoother& smoother = *best.smoother;
    for (int k = 0; k < steps; ++k) {
      const Key key = poseKey(static_cast<std::uint64_t>(k));
      result.poses.push_back(toPose(smoother.estimate().value(key)));
      result.poseCovariances.push_back(smoother.marginalCovariance(key));
    }
    for (const std::vector<int>& beta : best.history.steps()) {
      std::vector<std::optional<int>> ids;
      for (int id : beta) ids.push_back(id >= 0 ? std::optional<int>(id) : std::nullopt);
      result.associations.push_back(ids);
    }
    const Matrix& classMarginal = out.finalMarginals.classes;
    for (int j = 0; j < problem.objects(); ++j) {
      EstimatedLandmark landmark;
      landmark.id = problem.objectId(j);
      landmark.state = toLandmarkState(smoother.estimate().value(HybridProblem::objectKey(j)));
      if (classMarginal.size() > 0) landmark.classProbabilities = classMarginal.row(j).transpose();
      result.landmarks.push_back(landmark);
    }
    result.components = out.finalMarginals.components;
  }
  result.timeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start - observing).count();
  return out;
}

std::string describeBoundsThatBound(const std::vector<HybridStepReport>& reports, const HybridOptions& options) {
  int branched = 0, truncated = 0, capped = 0, memoryCapped = 0;
  double largestBound = 0.0, largestComponentBytes = 0.0;
  std::size_t largestCapped = 0, largestMemoryCapped = 0;
  for (const HybridStepReport& report : reports) {
    const PropWeightsReport& weights = report.weights;
    if (weights.branchedOneAtATime) {
      ++branched;
      largestBound = std::max(largestBound, weights.wholeAssociationBound);
    }
    if (weights.truncatedPartials > 0) ++truncated;
    if (report.cappedComponents > report.memoryCappedComponents) {
      ++capped;
      largestCapped = std::max(largestCapped, report.cappedComponents - report.memoryCappedComponents);
    }
    if (report.memoryCappedComponents > 0) {
      ++memoryCapped;
      largestMemoryCapped = std::max(largestMemoryCapped, report.memoryCappedComponents);
      largestComponentBytes = std::max(largestComponentBytes, report.componentBytes);
    }
  }
  std::ostringstream text;
  if (branched > 0) {
    text << "whole-association branching would have held up to " << largestBound << " candidates at a step (more "
         << "than --max-candidates " << options.maxCandidates << "), so " << branched
         << " step(s) branched one detection at a time (joint-compatibility test); ";
  }
  if (truncated > 0) {
    text << truncated << " step(s) kept only the " << options.maxCandidates
         << " heaviest partial associations (--max-candidates); ";
  }
  if (capped > 0) {
    text << "the component cap (--max-components " << options.maxComponents << ") dropped up to " << largestCapped
         << " components at " << capped << " step(s); ";
  }
  if (memoryCapped > 0) {
    text << "the memory bound (--max-memory " << options.maxMemoryMiB << " MiB, components of up to "
         << largestComponentBytes / (1024.0 * 1024.0) << " MiB) dropped up to " << largestMemoryCapped
         << " components at " << memoryCapped << " step(s); ";
  }
  std::string sentence = text.str();
  if (sentence.empty()) return sentence;
  sentence.resize(sentence.size() - 2);  // the last "; "
  return "the hybrid belief's memory bounds bound: " + sentence +
         " (docs/hybrid-belief.md, \"Bounded memory\": raise the bounds if memory allows)";
}

}  // namespace semslam
