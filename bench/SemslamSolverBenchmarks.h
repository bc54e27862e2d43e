#pragma once
// Our solvers on every dataset: semslam::optimize with Gauss-Newton and with Levenberg-Marquardt, from the
// file's initial values with the first-pose anchor. Each timed iteration is one complete optimize() call
// (layout of the normal equations, symbolic analysis, all iterations); the file is read before the timed loop.

#include "Datasets.h"

namespace semslam::bench {

/// Registers semslam_GN/<dataset> and semslam_LM/<dataset>.
void registerSemslamSolverBenchmarks(const Dataset& dataset);

}  // namespace semslam::bench
