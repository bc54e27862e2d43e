#pragma once
// HybridStudy: paper A's statistical study (sec. V, Fig. 5) on the aliased2d scenario, paired: for every alpha
// and every track, one simulated log (the same tracks, priors and geometric noise at every alpha, only the class
// scores change: sim/SimulationStreams.h), run twice, with the classifier model ("classifier") and geometric-only
// ("geometric"), on the same log.
//
// Per run (one row of runs.csv) at the final step: the four metrics of A sec. V (entropy over the association
// marginal eq. 8, det of the heaviest component's position covariance, x̃^{w_max}, x̃^{w_avg}), ESS, components,
// the NEES of the heaviest component's final pose, max_β P(β | H_k) at `disambiguationStep` and whether it
// exceeds 0.9, whether the heaviest history is the true one, and the run's time.
//
// Parallelism: runs are distributed over `threads` worker threads by an atomic counter; each run's Monte Carlo
// seed is derived from (seed, alpha index, track, model) only, and results are stored by run index, so the
// output does not depend on the thread count or the scheduling. The runs are listed (hybridStudyRuns) and run one
// by one (runHybridStudyRun) for a caller that spreads them further, over processes (apps/semslam/DistributedRuns.h).
// A run that throws is a row with NaN metrics and its error; the other runs go on.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "semslam/eval/Nees.h"
#include "semslam/hybrid/HybridOptions.h"
#include "semslam/sim/Aliased2dScenario.h"
#include "semslam/study/StudyLayout.h"

namespace semslam {

struct HybridStudyOptions {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  int tracks = 50;
  int steps = 10;
  std::vector<double> alphas{0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
  std::uint64_t seed = 1;
  HybridOptions hybrid;  ///< base options (samples, weights, pruning, gate); useSemantics and seed are set per run
  int threads = 2;
  int disambiguationStep = 5;
};

struct HybridStudyRow {
  double alpha = 0.0;
  std::string model;  ///< "classifier" or "geometric"
  int track = 0;
  double entropy = 0.0, detCov = 0.0, errWmax = 0.0, errWavg = 0.0, ess = 0.0;
  int components = 0;
  double finalNees = 0.0;                ///< NEES of the heaviest component's final pose (dof 3)
  double assocWeightAtStep = 0.0;        ///< max_β P(β | H_k) at the disambiguation step
  bool disambiguatedAtStep = false;      ///< > 0.9
  bool heaviestHistoryCorrect = false;   ///< the heaviest association history equals the truth
  double gateLostMass = 0.0;             ///< the largest per-step lost mass of the gate
  double analyticTotalVariation = 0.0;   ///< mean over steps (sampled runs)
  long long sampledCandidates = 0;
  double samplingSeconds = 0.0;        ///< wall-clock: timings.csv only
  double seconds = 0.0;                ///< wall-clock: timings.csv only
  std::string error;                   ///< non-empty: the run threw (metrics NaN); not in the CSV
};

/// One run of the study: the alpha (its index in options.alphas), the track and the model.
struct HybridStudyRun {
  std::size_t alphaIndex = 0;
  int track = 0;
  bool classifier = true;
};

/// The study's runs in row order (alphas, tracks inside, classifier then geometric); validates the options
/// (throws std::invalid_argument).
std::vector<HybridStudyRun> hybridStudyRuns(const HybridStudyOptions& options);

/// One run; its seed depends on (options.seed, alpha index, track, model) only. An exception inside the run is
/// caught into the row's error.
HybridStudyRow runHybridStudyRun(const HybridStudyOptions& options, const HybridStudyRun& run);

/// Runs the study; `progress(done, total)` is called (from the workers, serialised) after every run.
std::vector<HybridStudyRow> runHybridStudy(const HybridStudyOptions& options,
                                           const std::function<void(int, int)>& progress = {});

/// Runs whose row has an error.
int failedHybridRuns(const std::vector<HybridStudyRow>& rows);

/// runs.csv: every row but its times. summary.csv: alpha,model,entropy,det_cov,err_wmax,err_wavg, the means over
/// tracks. nees.csv: alpha,model,nees_mean,count,lower,upper (the pooled final-pose NEES and its 95 % band).
/// timings.csv (StudyLayout.h): alpha,model,track,rank,sampling_s,time_s,threads,ranks,wall_time_s, one row per
/// run (rank: the process that ran it; threads, ranks and the study's wall time repeated on every row). A job of
/// `layout` is a run. Every file is written atomically.
void writeHybridStudy(const std::string& directory, const std::vector<HybridStudyRow>& rows,
                      const StudyLayout& layout = {});

}  // namespace semslam
