#pragma once
// A mixture-heavy run of paper B's mm-nh (slam/SemanticSlam.h: one max-mixture per detection with candidates,
// warm start, null hypothesis) on each back end: the incremental smoother with its defaults (components chosen at
// the linearization point), the same with component re-choice at the new estimate (maxSwitchRounds 5:
// IncrementalSmoother.h, "Mixtures"; docs/association-front-end.md §6), and the batch smoother, which re-solves
// the whole graph at every update.
//
// The log: the semantic simulator (sim/SemanticSimulator.h) on a generated 2D loop driven twice (revisits),
// 300 steps of 1 m, 0.3 landmarks per metre, 3 classes, 10 % misclassification, 0.2 clutter detections per step,
// seed 1. Each timed iteration runs the whole log through runMethod (no covariances, no run folder). Counters:
//   ate_rmse     of the run's final estimate (m), so that a faster back end that loses the map shows;
//   da_accuracy  its association accuracy.
// Names have no '/', so the solver ratio table (RatioTable.h) ignores them; the median ratios batch/incremental
// are read off the medians (docs/association-front-end.md §6 reports them).

namespace semslam::bench {

/// Registers MixtureRun_incremental, MixtureRun_incremental_switching and MixtureRun_batch.
void registerMixtureRunBenchmarks();

}  // namespace semslam::bench
