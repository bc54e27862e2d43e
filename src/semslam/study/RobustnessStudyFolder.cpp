#include "semslam/study/RobustnessStudyFolder.h"

#include <filesystem>
#include <stdexcept>
#include <nlohmann/json.hpp>

#include "semslam/core/Version.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/run/MethodSettings.h"

namespace semslam {

int failedRobustnessRuns(const std::vector<RobustnessRow>& rows) {
  int failed = 0;
  for (const RobustnessRow& row : rows) failed += row.error.empty() ? 0 : 1;
  return failed;
}

namespace {

/// Each method's settings as its runs make them (run/MethodSettings.h), keyed by the method's name; for a method
/// that refuses the study's options (its runs failed, each with that error in robustness.csv), {"error": why}.
nlohmann::json methodSettingsOf(const RobustnessStudyOptions& options) {
  nlohmann::json settings = nlohmann::json::object();
  for (const AssociationStrategy strategy : options.methods) {
    MethodOptions run;  // as runRobustnessCell makes each run's
    run.method = methodFor(strategy);
    run.slam = options.slam;
    run.poseCovariances = false;
    try {
      settings[strategyName(strategy)] = methodSettings(run);
    } catch (const std::invalid_argument& error) {
      settings[strategyName(strategy)] = {{"error", error.what()}};
    }
  }
  return settings;
}

}  // namespace

std::string robustnessStudyJson(const RobustnessStudy& study, const RobustnessStudyOptions& options,
                                const RobustnessStudyLabels& labels) {
  const nlohmann::json settings = {
      {"schema", "semslam.study.robustness/3"},
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
      {"smoother", labels.smoother},
      {"method_settings", methodSettingsOf(options)},
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
