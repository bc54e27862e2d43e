#pragma once
// HybridStudy: paper A's statistical study (sec. V, Fig. 5), paired: for every layout, alpha and track, one simulated
// log (the same tracks, priors and geometric noise at every alpha, only the class scores change:
// sim/SimulationStreams.h), run with the classifier model ("classifier") and geometric-only ("geometric").
//
// The geometric model reads no class score, and the scores are all that alpha changes, so its run on a track is the
// same inference at every alpha: it runs once per layout and track (on the first alpha's log, with that alpha's
// Monte Carlo seed) and its row is reported at every alpha (hybridStudyTable), paired with each alpha's classifier
// run. The test HybridStudy.TheGeometricRunDoesNotDependOnAlpha holds the premise. A study of A alphas thus makes
// A + 1 runs per track, not 2A (7 instead of 12 for the Fig. 5 analog), and the geometric curve of the alpha sweep
// is flat, as the model is, instead of varying with the Monte Carlo seed.
//
// Layouts. Paper A studies many tracks in one scattered layout; one layout's answer may be the layout's, so the study
// runs several: by default 10 seeded layouts of sim/Aliased2dLayout.h (layout seeds 1 … 10), or the scenario files a
// user gives (the hand-made parking aisle and four-bay layouts are stress tests). Layout L's tracks come from the
// seed layoutTrackSeed(seed, L), so layouts do not share track shapes.
//
// Per run (one row of runs.csv) at the final step: the four metrics of A sec. V (entropy over the association
// marginal eq. 8, det of the heaviest component's position covariance, x̃^{w_max}, x̃^{w_avg}), ESS, components,
// the NEES of the heaviest component's final pose and whether that component's history is the true one (the NEES
// of a component whose history is right measures its Gaussian's consistency; a wrong history is a different
// question, answered by the error), the NEES of the moment-matched mixture of every component's final pose
// (eval/PoseMixtureMoments.h: the consistency of the belief as a whole), max_β P(β | H_k) at `disambiguationStep`
// and whether it exceeds 0.9, whether the heaviest association history (eq. 8) is the true one, and the run's time.
//
// Parallelism: runs are distributed over `threads` worker threads by an atomic counter; each run's Monte Carlo
// seed is derived from (seed, layout, alpha index, track, model) only, and results are stored by run index, so the
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

/// The default layouts: generated layouts `firstSeed` … firstSeed + count − 1 (sim/Aliased2dLayout.h).
std::vector<Aliased2dScenario> generatedHybridStudyLayouts(std::uint64_t firstSeed = 1, int count = 10);

/// The seed of layout L's tracks: `seed` mixed with L (a splitmix64 step), so that layouts do not share track shapes.
std::uint64_t layoutTrackSeed(std::uint64_t seed, std::size_t layout);

struct HybridStudyOptions {
  std::vector<Aliased2dScenario> layouts = generatedHybridStudyLayouts();
  int tracks = 50;  ///< per layout and alpha
  int steps = 10;
  std::vector<double> alphas{0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
  std::uint64_t seed = 1;
  HybridOptions hybrid;  ///< base options (samples, weights, pruning, gate); useSemantics and seed are set per run
  int threads = 2;
  int disambiguationStep = 5;
};

struct HybridStudyRow {
  int layout = 0;       ///< index into options.layouts
  double alpha = 0.0;
  std::string model;  ///< "classifier" or "geometric"
  int track = 0;
  double entropy = 0.0, detCov = 0.0, errWmax = 0.0, errWavg = 0.0, ess = 0.0;
  int components = 0;
  double finalNees = 0.0;                ///< NEES of the heaviest component's final pose (dof 3)
  bool heaviestComponentCorrect = false; ///< the heaviest component's history equals the truth
  double mixtureNees = 0.0;              ///< NEES of the moment-matched mixture of the final poses (dof 3)
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

/// One run of the study: the layout and alpha (indices in options.layouts and options.alphas), the track and the model.
struct HybridStudyRun {
  std::size_t layout = 0;
  std::size_t alphaIndex = 0;
  int track = 0;
  bool classifier = true;
};

/// The study's runs (layouts, alphas inside, tracks inside; the classifier, then, at the first alpha only, the
/// geometric model); validates the options (throws std::invalid_argument).
std::vector<HybridStudyRun> hybridStudyRuns(const HybridStudyOptions& options);

/// The study's table from the rows of its runs (`executed[i]` the row of hybridStudyRuns(options)[i]): for every
/// layout, alpha and track, the classifier row of that alpha, then the track's geometric row with its alpha set to
/// that alpha (the same run at every alpha, above).
std::vector<HybridStudyRow> hybridStudyTable(const HybridStudyOptions& options,
                                             const std::vector<HybridStudyRow>& executed);

/// One run; its seeds depend on (options.seed, layout, alpha index, track, model) only. An exception inside the run is
/// caught into the row's error.
HybridStudyRow runHybridStudyRun(const HybridStudyOptions& options, const HybridStudyRun& run);

/// Runs the study: one row per run of hybridStudyRuns, in its order (hybridStudyTable makes the table of them);
/// `progress(done, total)` is called (from the workers, serialised) after every run.
std::vector<HybridStudyRow> runHybridStudy(const HybridStudyOptions& options,
                                           const std::function<void(int, int)>& progress = {});

/// Runs whose row has an error.
int failedHybridRuns(const std::vector<HybridStudyRow>& rows);

/// `executed`: the rows of the runs, as runHybridStudy returns them. runs.csv: every row of hybridStudyTable but its
/// times (layout is the index into layouts.csv). layouts.csv: layout,name,objects, and
/// every layout as a scenario file layouts/layout_<L>.json (rerun one with --scenario). summary.csv:
/// alpha,model,entropy,det_cov,err_wmax,err_wavg,heaviest_correct, the means over layouts and tracks (per-layout
/// statistics: python/plot_hybrid.py). nees.csv: alpha,model,subset,nees_mean,count,lower,upper, the pooled NEES
/// and its 95 % band for the subsets "heaviest" (every run's heaviest component), "heaviest_correct" and
/// "heaviest_wrong" (split by whether that component's history is the true one) and "mixture" (the moment-matched
/// mixture); failed runs are left out of every subset. timings.csv (StudyLayout.h):
/// layout,alpha,model,track,rank,sampling_s,time_s,threads,ranks,wall_time_s, one row per run (rank: the process
/// that ran it; threads, ranks and the study's wall time repeated on every row). A job of `jobs` is a run. Every
/// file is written atomically.
void writeHybridStudy(const std::string& directory, const HybridStudyOptions& options,
                      const std::vector<HybridStudyRow>& executed, const StudyLayout& jobs = {});

}  // namespace semslam
