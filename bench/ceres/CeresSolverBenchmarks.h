#pragma once
// Ceres Solver on the same problems as our solvers (Datasets.h), with the settings of ceresOptions():
//   ceres_LM_1t, ceres_LM_2t       our factors wrapped (CeresPoseGraph), 1 and 2 threads;
//   ceres_autodiff_LM_1t           Ceres's own autodiff SE2 residuals (AutodiffPoseGraph2), for the 2D pose
//                                  graphs without landmarks (Dataset::planarPosesOnly), 1 thread.
// Each timed iteration builds the ceres::Problem from the graph and solves it, as one optimize() call of ours
// lays out its normal equations and solves. The final chi2 is over the file's own edges, as for ours.

#include "Datasets.h"

namespace semslam::bench {

/// Registers the Ceres benchmarks of `dataset`.
void registerCeresSolverBenchmarks(const Dataset& dataset);

}  // namespace semslam::bench
