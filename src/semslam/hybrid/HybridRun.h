#pragma once
// HybridRun: paper A's hybrid belief run over a whole measurement log, step by step. What the belief said at each
// step (HybridMarginals) and what its update did (HybridStepReport) go to an observer as they happen and are not
// kept: a run holds the current belief, one report per step and the last step's marginals, so its memory does not
// grow with steps × components × history length. The final estimate is a RunResult (models/RunResult.h):
//   poses, poseCovariances   the heaviest final component's smoothed poses and their marginal covariances;
//   associations             its association history (log ids; std::nullopt for a dropped detection);
//   landmarks                its object estimates, with the class marginal (eq. 7) where semantics are used;
//   components               the final belief's components; heaviestAssociationWeights: max_β P(β | H_k) per step;
//   timeSeconds              the loop's wall time, each step's marginals included, the observer's time excluded.
// method is "hybrid" (semantics) or "hybrid-geometric" (options.useSemantics = false).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "semslam/models/RunResult.h"
#include "semslam/hybrid/HybridBelief.h"
#include "semslam/hybrid/HybridMarginals.h"

namespace semslam {

struct HybridStepRecord {
  HybridStepReport report;
  HybridMarginals marginals;
};

struct HybridRunOutput {
  RunResult result;
  std::vector<HybridStepReport> reports;  ///< one per step
  HybridMarginals finalMarginals;         ///< what the belief said at the last step
};

/// Progress callback: (steps done, steps in all).
using HybridProgress = std::function<void(int, int)>;
/// Called after each step with what the belief said and did then; the record dies when it returns.
using HybridStepObserver = std::function<void(const HybridStepRecord&)>;

/// What the memory bounds of `options` (HybridOptions: maxCandidates, maxComponents, maxMemoryMiB) did over a
/// run, as a sentence a user can act on; empty when no bound bound at any step.
std::string describeBoundsThatBound(const std::vector<HybridStepReport>& reports, const HybridOptions& options);

/// Runs the log (InputError for a log the hybrid belief cannot take: HybridProblem.h).
HybridRunOutput runHybrid(const MeasurementLog& log, const HybridOptions& options,
                          const HybridProgress& progress = {}, const HybridStepObserver& observer = {});

}  // namespace semslam
