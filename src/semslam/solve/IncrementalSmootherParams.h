#pragma once
// IncrementalSmootherParams: the policies of the incremental smoother (IncrementalSmoother.h), named after the
// iSAM2 parameters they correspond to (Kaess et al., "iSAM2: Incremental smoothing and mapping using the Bayes
// tree", IJRR 2012, Alg. 6 and Sec. V).
//
//   relinearizeThreshold  fluid relinearization: a variable whose accumulated update ‖Δ_v‖∞ (tangent, right
//                         perturbation) exceeds this is relinearized, θ_v ← θ_v ⊕ Δ_v, and every factor touching it
//                         is re-linearized and re-eliminated (iSAM2's β);
//   relinearizeSkip       check for relinearization every this many updates (1: every update);
//   wildfireThreshold     partial state update: back-substitution descends into an unchanged subtree only if some
//                         variable of its separator moved by more than this (iSAM2's α); 0 solves exactly;
//   relaxedCliqueFrontals, relaxedCliqueZeros
//                         relaxed supernode amalgamation (as CHOLMOD's nrelax/zrelax): a variable joins its parent's
//                         clique while that clique has fewer than relaxedCliqueFrontals frontals and the variable's
//                         row in it would be at most this fraction of explicit zeros; fewer, larger dense cliques
//                         (1 and 0 keep fundamental supernodes only).
//
// The defaults are GTSAM's own ISAM2Params defaults (0.1, 10, 0.001); docs/incremental-smoother.md gives the
// figures for these and for the stricter 0.01 / 1 setting the iSAM2 reference run used. `semslam optimize
// --incremental` and `semslam run` (paper B's methods) take the first two as --relinearize-threshold and
// --relinearize-skip (MethodOptions, docs/association-front-end.md §10). Paper B's methods start from their own
// settings, 0.05 at every update (slam/SemanticSlamSmoother.h: graphs of max-mixtures, swept there).
//
//   reorderFillGrowth     need-based reordering: when the factor holds more than this many times the entries per
//                         variable it held right after the last full ordering, the next update re-orders and
//                         re-eliminates the whole tree (with cached linearizations); 0 never does.
//   maxSwitchRounds       mixtures (factors with Factor::activeComponent ≥ 0, e.g. paper B's max-mixtures): after
//                         an update's solve, a mixture whose component active at the new estimate θ ⊕ Δ differs
//                         from the one it was linearized with has its variables relinearized there and the update
//                         solves again, until no mixture switches or this many extra solves were made (the
//                         incremental counterpart of the batch smoother choosing at every Gauss-Newton iterate;
//                         IncrementalSmoother.h, docs/incremental-smoother.md "Mixtures"). 0, the default, turns
//                         re-choosing off (components chosen at θ only, the behaviour before issue 10 §6): measured
//                         on the logs of docs/association-front-end.md §6, 5 rounds do not bring the incremental
//                         ATE to the batch back end's, make mm much worse (KITTI 00: 39 m → 186 m; MRCLAM robot 1:
//                         0.24 → 0.61 m) and, for mm-nh, follow the batch back end into its worse estimates on
//                         MRCLAM (session 26: ATE higher on 11 of 15 runs, da_accuracy_real 0.546 → 0.511, while
//                         KITTI tracking's +0.03 is within its runs' spread; 1.4× the time on Lost in the Woods), so
//                         it stays opt-in.
//                         `semslam run --switch-rounds N` sets it (MethodOptions::switchRounds).
//                         A graph without mixtures is solved bit for bit the same whatever the value.

namespace semslam {

struct IncrementalSmootherParams {
  double relinearizeThreshold = 0.1;
  int relinearizeSkip = 10;
  double wildfireThreshold = 0.001;
  double reorderFillGrowth = 2.0;
  int relaxedCliqueFrontals = 4;
  double relaxedCliqueZeros = 0.5;
  int maxSwitchRounds = 0;
};

}  // namespace semslam
