#pragma once
// One step of paper A's Algorithm 1 (HybridBelief::update: propagate, PropWeights, prune, update) on a fixed
// seeded belief, with each weight method: sampled (A, eq. 17, plain Monte Carlo over the joint marginal),
// importance (linearised-posterior proposal) and analytic (linearised closed form).
//
// The belief: the default aliased2d layout (classifier model, alpha 0.25), track 0 of seed 1, updated up to the
// first step that has detections; each timed iteration copies that belief (a copy shares every smoother and the
// random engine's state, so every iteration does the same work) and applies the step. Counters:
//   samples_per_s   Monte Carlo draws (sampled candidates × samples) per second of wall time (0 for analytic);
//   weights_per_s   candidate weights computed (sampled or linearised) per second;
//   candidates, sampled, survivors   of the timed step.
// Names have no '/', so the solver ratio table (RatioTable.h) ignores them.

namespace semslam::bench {

/// Registers HybridStep_sampled, HybridStep_importance and HybridStep_analytic.
void registerHybridStepBenchmarks();

}  // namespace semslam::bench
