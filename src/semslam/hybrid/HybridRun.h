#pragma once
// HybridRun: paper A's hybrid belief run over a whole measurement log, step by step, recording what the belief
// said at every step (HybridMarginals) and what each update did (HybridStepReport), and the final estimate as
// a RunResult (models/RunResult.h):
//   poses, poseCovariances   the heaviest final component's smoothed poses and their marginal covariances;
//   associations             its association history (log ids; std::nullopt for a dropped detection);
//   landmarks                its object estimates, with the class marginal (eq. 7) where semantics are used;
//   components               the final belief's components; heaviestAssociationWeights: max_β P(β | H_k) per step.
// method is "hybrid" (semantics) or "hybrid-geometric" (options.useSemantics = false).

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
  std::vector<HybridStepRecord> steps;
};

/// Progress callback: (steps done, steps in all).
using HybridProgress = std::function<void(int, int)>;

/// What the memory bounds of `options` (HybridOptions: maxCandidates, maxComponents) did over a run, as a sentence a
/// user can act on; empty when no bound bound at any step.
std::string describeBoundsThatBound(const std::vector<HybridStepRecord>& steps, const HybridOptions& options);

/// Runs the log (InputError for a log the hybrid belief cannot take: HybridProblem.h).
HybridRunOutput runHybrid(const MeasurementLog& log, const HybridOptions& options,
                          const HybridProgress& progress = {});

}  // namespace semslam
