#include "semslam/hybrid/HybridRun.h"

#include <chrono>

namespace semslam {

HybridRunOutput runHybrid(const MeasurementLog& log, const HybridOptions& options, const HybridProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const HybridProblem problem(log.header, options.useSemantics);
  HybridBelief belief(problem, options);
  HybridRunOutput out;
  const int steps = static_cast<int>(log.steps.size());
  for (int k = 0; k < steps; ++k) {
    HybridStepRecord record;
    record.report = belief.update(log.steps[k]);
    record.marginals = hybridMarginals(belief);
    out.result.heaviestAssociationWeights.push_back(record.marginals.association.front().weight);  // max_β P(β | H_k)
    out.steps.push_back(std::move(record));
    if (progress) progress(k + 1, steps);
  }

  RunResult& result = out.result;
  result.method = options.useSemantics ? "hybrid" : "hybrid-geometric";
  if (!out.steps.empty()) {
    const HybridComponent& best = belief.components()[belief.heaviest()];
    const Smoother& smoother = *best.smoother;
    for (int k = 0; k < steps; ++k) {
      const Key key = poseKey(static_cast<std::uint64_t>(k));
      result.poses.push_back(smoother.estimate<SE2>(key));
      result.poseCovariances.push_back(smoother.marginalCovariance(key));
    }
    for (const std::vector<int>& beta : best.history) {
      std::vector<std::optional<int>> ids;
      for (int object : beta) {
        ids.push_back(object >= 0 ? std::optional<int>(problem.objectId(object)) : std::nullopt);
      }
      result.associations.push_back(ids);
    }
    const Matrix& classMarginal = out.steps.back().marginals.classes;
    for (int j = 0; j < problem.objects(); ++j) {
      EstimatedLandmark landmark;
      landmark.id = problem.objectId(j);
      std::visit(
          [&](const auto& v) {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, Point2> || std::is_same_v<V, SE2>) landmark.state = v;
          },
          smoother.estimate().value(HybridProblem::objectKey(j)));
      if (classMarginal.size() > 0) landmark.classProbabilities = classMarginal.row(j).transpose();
      result.landmarks.push_back(landmark);
    }
    result.components = out.steps.back().marginals.components;
  }
  result.timeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace semslam
