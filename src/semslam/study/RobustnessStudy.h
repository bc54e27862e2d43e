#pragma once
// RobustnessStudy: paper B's robustness study (sec. V-A, Fig. 3) on one measurement log: two one-axis sweeps,
//   odom_noise         the odometry noise scale s over its levels, at misclassification noiseSweepMisclassification
//                      (0.1);
//   misclassification  the misclassification rate p over its levels, at odometry noise scale
//                      misclassificationSweepNoiseScale (1),
// each level run with `seeds` seeds. A cell is (axis, level, seed): its perturbed log (LogPerturbation.h) is built
// once, from perturbation seed baseSeed + seed, and every method runs on that same log (paired seeds). Cells run in
// parallel on `threads` worker threads (a shared queue); results are stored by cell index, so the rows do not
// depend on the thread count (except timeSeconds, a wall-clock time that only timings.csv holds). A caller that
// spreads the cells further, over processes (apps/semslam/DistributedRuns.h), runs them one by one
// (runRobustnessCell). docs/robustness-study.md describes the study.
//
// Stuck (paper B, sec. V-A: max-mixtures "stuck" in a local optimum between hypotheses): a mm or mm-nh run is stuck
// when its ATE RMSE exceeds both stuckRatio (3) times and stuckMargin (0.1 m) more than the ATE RMSE of `known` on
// the same cell: the same perturbed log solved with the true associations, so the excess is the association's
// fault. Undefined (empty) for other methods, when `known` is not run, or when either ATE is not finite.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "semslam/slam/SemanticSlam.h"
#include "semslam/study/LogPerturbation.h"
#include "semslam/study/StudyLayout.h"

namespace semslam {

enum class RobustnessAxis { OdometryNoise, Misclassification };

/// "odom_noise", "misclassification".
std::string robustnessAxisName(RobustnessAxis axis);

struct RobustnessStudyOptions {
  std::vector<AssociationStrategy> methods = allStrategies();
  std::vector<double> noiseScales = {0, 1, 2, 5, 10};
  std::vector<double> misclassificationRates = {0, 0.1, 0.2, 0.3, 0.5};
  int seeds = 10;
  std::uint64_t baseSeed = 0;
  double noiseSweepMisclassification = 0.1;
  double misclassificationSweepNoiseScale = 1.0;
  int threads = 2;
  int maxSteps = 0;  ///< > 0: only the log's first maxSteps steps
  SemanticSlamOptions slam;  ///< strategy is set per method; the smoother factory must be callable from any thread
  OdometryNoiseBaseline baseline;
  double stuckRatio = 3.0;
  double stuckMargin = 0.1;  ///< m
  /// The methods' model rate is max(p, this) (LogPerturbation::modelMisclassificationFloor); 0: the exact rate.
  double modelMisclassificationFloor = 0.0;
  /// Called after every finished run (cell × method) with (finished, total), from the worker threads but never
  /// concurrently.
  std::function<void(int, int)> progress;
};

struct RobustnessCell {
  RobustnessAxis axis = RobustnessAxis::OdometryNoise;
  double level = 0.0;
  int seed = 0;                    ///< 0 .. seeds − 1
  LogPerturbation perturbation;    ///< what the cell's log gets
  std::uint64_t perturbationSeed = 0;
};

struct RobustnessRow {
  RobustnessAxis axis = RobustnessAxis::OdometryNoise;
  double level = 0.0;
  int seed = 0;
  std::string method;
  double ateRmse = 0.0, rotRmse = 0.0, daAccuracy = 0.0;  ///< NaN where not applicable or the run failed
  double daAccuracyReal = 0.0;     ///< over detections of true landmarks only (docs/metrics.md); NaN likewise
  std::optional<long long> landmarksEstimated, landmarksTrue;
  double timeSeconds = 0.0;        ///< wall-clock: timings.csv only
  std::optional<bool> stuck;
  std::string error;  ///< non-empty: the run threw (metrics NaN); not in the CSV
};

struct RobustnessStudy {
  std::vector<RobustnessRow> rows;  ///< cell order (odom_noise levels, then misclassification levels; seeds inside),
                                    ///< methods in the options' order within a cell
  StudyLayout layout;               ///< a job is a cell; wall time, threads, ranks (timings.csv)
};

/// Validates the options (throws std::invalid_argument naming the problem: no methods, an empty level list, a
/// negative or non-finite scale, p outside [0, 1), seeds < 1, threads < 1, maxSteps < 0).
void validateRobustnessOptions(const RobustnessStudyOptions& options);

/// The cells, in row order.
std::vector<RobustnessCell> robustnessCells(const RobustnessStudyOptions& options);

/// One cell: its perturbed log, every method on it (a method that throws leaves a row with its error), the stuck
/// rule against known; `runFinished()` after each method's run. Throws when the log cannot be perturbed.
std::vector<RobustnessRow> runRobustnessCell(const MeasurementLog& log, const RobustnessStudyOptions& options,
                                             const RobustnessCell& cell,
                                             const std::function<void()>& runFinished = {});

RobustnessStudy runRobustnessStudy(const MeasurementLog& log, const RobustnessStudyOptions& options);

/// CSV: axis,level,seed,method,ate_rmse,rot_rmse,da_accuracy,da_accuracy_real,landmarks_estimated,landmarks_true,
/// stuck (numbers in shortest round-trip form, NaN and absent values empty, stuck 0/1 or empty).
std::string robustnessCsv(const std::vector<RobustnessRow>& rows);

/// timings.csv: axis,level,seed,method,rank,time_s,threads,ranks,wall_time_s, one row per run in row order (rank:
/// the process that ran the run's cell; threads, ranks and the study's wall time repeated on every row).
std::string robustnessTimingsCsv(const std::vector<RobustnessRow>& rows, const StudyLayout& layout,
                                 std::size_t methodsPerCell);

/// Mean and two-sided 95% Student-t confidence interval of the finite values (n < 2: the interval is NaN).
struct MeanInterval {
  int n = 0;
  double mean = 0.0, low = 0.0, high = 0.0;
};
MeanInterval meanInterval(const std::vector<double>& values);
/// The 0.975 quantile of Student's t with `dof` degrees of freedom (exact table to 30, Cornish–Fisher beyond).
double studentT975(int dof);

/// Summary CSV, one row per (axis, level, method) in row order:
/// axis,level,method,n,ate_mean,ate_ci_low,ate_ci_high,rot_mean,rot_ci_low,rot_ci_high,da_mean,da_ci_low,
/// da_ci_high,da_real_mean,da_real_ci_low,da_real_ci_high,landmarks_mean,stuck_fraction,failed
std::string robustnessSummaryCsv(const std::vector<RobustnessRow>& rows);

}  // namespace semslam
