#include "semslam/study/RobustnessStudyFolder.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "semslam/core/Version.h"
#include "semslam/io/AtomicFile.h"

namespace semslam {

int failedRobustnessRuns(const std::vector<RobustnessRow>& rows) {
  int failed = 0;
  for (const RobustnessRow& row : rows) failed += row.error.empty() ? 0 : 1;
  return failed;
}

std::string robustnessStudyJson(const RobustnessStudy& study, const RobustnessStudyOptions& options,
                                const RobustnessStudyLabels& labels) {
  const nlohmann::json settings = {
      {"schema", "semslam.study.robustness/2"},
      {"version", std::string(version())},
      {"log", labels.log},
      {"methods", labels.methods},
      {"odom_noise_scales", options.noiseScales},
      {"misclassification_rates", options.misclassificationRates},
      {"noise_sweep_misclassification", options.noiseSweepMisclassification},
      {"misclassification_sweep_noise_scale", options.misclassificationSweepNoiseScale},
      {"baseline_sigma_per_second", {options.baseline.sigmaX, options.baseline.sigmaY, options.baseline.sigmaTheta}},
      {"seeds", options.seeds},
      {"base_seed", options.baseSeed},
      {"max_steps", options.maxSteps},
      {"gate", options.slam.gateConfidence},
      {"null_weight", options.slam.nullWeight},
      {"null_sigma_scale", options.slam.nullSigmaScale},
      {"em_window", options.slam.emWindow},
      {"em_iterations", options.slam.emIterations},
      {"birth", birthRuleName(options.slam.birth)},
      {"unassigned_rate", options.slam.unassignedRate},
      {"unassigned_rate_weight", options.slam.unassignedRateWeight ? nlohmann::json(*options.slam.unassignedRateWeight)
                                                                    : nlohmann::json(nullptr)},
      {"smoother", labels.smoother},
      {"warm_start", options.slam.warmStart},
      {"label_split", options.slam.labelSplit},
      {"assignment_score", assignmentScoreName(resolvedAssignmentScore(options.slam))},
      {"model_misclassification_floor", options.modelMisclassificationFloor},
      {"stuck_ratio", options.stuckRatio},
      {"stuck_margin_m", options.stuckMargin},
      {"runs", study.rows.size()},
      {"failed_runs", failedRobustnessRuns(study.rows)},
  };
  return settings.dump(2) + "\n";
}

void writeRobustnessStudyFolder(const std::string& directory, const RobustnessStudy& study,
                                const RobustnessStudyOptions& options, const RobustnessStudyLabels& labels) {
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  const auto write = [&directory](const char* name, const std::string& text) {
    writeFileAtomically((fs::path(directory) / name).string(), [&text](std::ostream& out) { out << text; });
  };
  write("robustness.csv", robustnessCsv(study.rows));
  write("robustness_summary.csv", robustnessSummaryCsv(study.rows));
  write("study.json", robustnessStudyJson(study, options, labels));
  write("timings.csv", robustnessTimingsCsv(study.rows, study.layout, options.methods.size()));
}

}  // namespace semslam
