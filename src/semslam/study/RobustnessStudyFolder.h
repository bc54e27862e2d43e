#pragma once
// RobustnessStudyFolder: the folder of paper B's robustness study (RobustnessStudy.h; docs/robustness-study.md),
// which python/plot_robustness.py draws:
//   robustness.csv          one row per axis, level, seed and method (robustnessCsv)
//   robustness_summary.csv  mean and 95% t-interval per axis, level and method (robustnessSummaryCsv)
//   study.json              schema "semslam.study.robustness/2", version (the semslam release that wrote it,
//                           core/Version.h): the settings the study ran with (log, methods,
//                           levels, seeds, paper B's options: gate, null_weight, null_sigma_scale, em_window,
//                           em_iterations, warm_start, label_split; smoother, model floor, stuck rule), the number
//                           of runs and failed runs (/1 also held threads and the wall time: now in timings.csv)
//   timings.csv             every run's time, the rank that ran it, threads, ranks, the study's wall time
//                           (robustnessTimingsCsv): the one file that differs between layouts (StudyLayout.h)
// Every file is written atomically; the folder is created if needed.

#include <string>
#include <vector>

#include "semslam/study/RobustnessStudy.h"

namespace semslam {

/// What study.json names as the user gave it (the options hold them in a form that cannot be printed back).
struct RobustnessStudyLabels {
  std::string log;       ///< the measurement log's path
  std::string methods;   ///< the method list as given, e.g. "known,ml,gpda,mm,mm-nh"
  std::string smoother;  ///< incremental | batch
};

/// Runs whose method threw (their row's error is non-empty).
int failedRobustnessRuns(const std::vector<RobustnessRow>& rows);

/// study.json's text (2-space indent, a final newline).
std::string robustnessStudyJson(const RobustnessStudy& study, const RobustnessStudyOptions& options,
                                const RobustnessStudyLabels& labels);

void writeRobustnessStudyFolder(const std::string& directory, const RobustnessStudy& study,
                                const RobustnessStudyOptions& options, const RobustnessStudyLabels& labels);

}  // namespace semslam
