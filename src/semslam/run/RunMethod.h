#pragma once
// RunMethod: where a run happens. runMethod drives one estimation method of either paper over a whole measurement
// log, scores its final estimate against the log's truth (eval/RunEvaluation.h) and builds its run folder
// (io/RunFolder.h); writeMethodRun writes that folder. Every caller — `semslam run`, `semslam demo`, the studies
// (study/) — goes through these two functions, so a run is driven, scored and written the same way for every
// method (the benchmarks time single estimator steps directly).
//
//   known | ml | gpda | mm | mm-nh   paper B's pipeline (slam/SemanticSlam.h) with `options.slam`; its
//                                    strategy is the method's. Back end: the incremental smoother.
//   hybrid | hybrid-geometric        paper A's hybrid belief (hybrid/HybridRun.h) with `options.hybrid`;
//                                    useSemantics is the method's. Back end: batch Levenberg-Marquardt.
// `options.smoother`, when set, replaces the method's back end. `options.switchRounds` > 0 lets the incremental
// back end re-choose max-mixture components at its new estimate (IncrementalSmootherParams::maxSwitchRounds,
// docs/association-front-end.md §6): only for mm and mm-nh (no other method has a mixture to switch) on the
// incremental back end (the batch one re-chooses at every Gauss-Newton iterate anyway); elsewhere it is refused.
//
// The run folder (`output`, written by writeMethodRun): metrics.json (io/RunMetricsFile.h), settings.json
// (run/MethodSettings.h: the method and every option it ran with), trajectory.tum,
// truth.tum, landmarks.csv, landmarks_truth.csv, covariances.csv, associations.csv (io/RunFolder.h), and for the
// hybrid methods hypotheses.jsonl (io/HypothesesJsonl.h: every step's belief and its metrics, spooled to a
// temporary file as the run goes, so that a long run does not hold them in memory). An association's
// weight is the method's own: paper B's normalised association probability of the chosen landmark, paper A's
// association marginal P(β_1:k | H_k) (A, eq. 8) of the heaviest component's history.
//
// result.timeSeconds is the estimator's wall time as the estimator measures it (paper B: the pipeline's steps and
// final convergence; paper A: runHybrid's loop, which includes each step's marginals): scoring and building the
// folder are excluded.

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/eval/RunEvaluation.h"
#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"
#include "semslam/hybrid/HybridOptions.h"
#include "semslam/hybrid/HybridRun.h"
#include "semslam/io/RunFolder.h"
#include "semslam/io/SpooledText.h"
#include "semslam/run/Method.h"
#include "semslam/slam/SemanticSlam.h"
#include "semslam/solve/SmootherFactory.h"

namespace semslam {

struct MethodOptions {
  Method method = Method::MaxMixtureNullHypothesis;
  std::optional<SmootherKind> smoother;  ///< empty: the method's default back end (above)
  int switchRounds = 0;                  ///< incremental back end, mm and mm-nh: IncrementalSmootherParams::maxSwitchRounds
  /// Paper B's methods on the incremental back end: IncrementalSmootherParams' fluid relinearization (iSAM2's β and
  /// its skip); empty: paper B's defaults (slam/SemanticSlamSmoother.h: 0.05, every update). The front end gates each step on
  /// the estimate and its marginal at the linearization point, so how fresh that point is can change decisions
  /// (docs/association-front-end.md §10, "The incremental estimate after a large closure").
  std::optional<double> relinearizeThreshold;
  std::optional<int> relinearizeSkip;
  SemanticSlamOptions slam;              ///< paper B's methods (`strategy` and `smoother` are set from the above)
  HybridOptions hybrid;                  ///< paper A's methods (`useSemantics` is set from the method)
  bool poseCovariances = true;           ///< paper B: the marginal covariance of every pose (NEES, ellipses)
  bool runFolder = true;                 ///< build `output` (and, for hybrid, every step's metrics)
  bool keepFinalGraph = false;           ///< paper B: keep the final factor graph and estimate in the run
};

struct MethodRun {
  Method method = Method::MaxMixtureNullHypothesis;
  RunResult result;          ///< the final estimate
  RunEvaluation evaluation;  ///< scored against the log's truth
  RunOutput output;          ///< the run folder's contents (when options.runFolder)
  std::size_t factors = 0;   ///< paper B: factors in the final graph
  int jointSearchesStopped = 0;  ///< paper B, AssignmentScore::Joint: steps whose search stopped at its budget
  FactorGraph finalGraph;    ///< paper B, with options.keepFinalGraph: the smoother's factors at the end
  Values finalEstimate;      ///< ... and its estimate (every pose k under poseKey(k))
  std::vector<HybridStepReport> hybridReports;      ///< paper A: what the update did at every step
  std::vector<HypothesisMetrics> hybridStepMetrics; ///< paper A: eval's metrics of the belief at every step
  HybridMarginals hybridFinal;                      ///< paper A: what the belief said at the last step
  std::optional<SpooledText> hypothesesJsonl;       ///< paper A: hypotheses.jsonl's lines (options.runFolder)
  bool hasRunFolder = false;                        ///< `output` was built (options.runFolder)
  nlohmann::json settings;   ///< what the run was made with (run/MethodSettings.h): the folder's settings.json
};

/// Progress callback: (steps done, steps in all).
using RunProgress = std::function<void(int, int)>;

/// Runs `options.method` over `log`. Throws InputError for a log the method cannot take, std::invalid_argument for
/// options it cannot take.
MethodRun runMethod(const MeasurementLog& log, const MethodOptions& options, const RunProgress& progress = {});

/// Writes run.output, metrics.json and (hybrid) hypotheses.jsonl into `directory` (created if needed). Throws
/// std::invalid_argument for a run made without options.runFolder.
void writeMethodRun(const std::string& directory, const MethodRun& run);

}  // namespace semslam
