#include "semslam/slam/SemanticSlamRun.h"

#include <chrono>

#include "semslam/io/RunOutputFromResult.h"

namespace semslam {

SemanticSlamRun runSemanticSlam(const MeasurementLog& log, const SemanticSlamRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SemanticSlam slam(log.header, options.slam);
  for (const TimeStep& step : log.steps) slam.addStep(step);
  slam.finish();
  SemanticSlamRun run;
  run.result = slam.result(options.poseCovariances);
  run.result.timeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.factors = slam.smoother().factors().size();
  run.evaluation = evaluateRun(log, run.result);
  if (options.runFolder) {
    std::vector<AssociationRecord> associations;
    for (const DetectionRecord& record : slam.detections()) {
      const auto [landmark, weight] = slam.chosenAssociation(record);
      if (options.slam.strategy == AssociationStrategy::Known && !landmark) continue;  // clutter: no factor
      associations.push_back({record.step, record.detection, landmark, weight, record.truth});
    }
    run.output = runOutputFrom(log, run.result, std::move(associations));
  }
  return run;
}

}  // namespace semslam
