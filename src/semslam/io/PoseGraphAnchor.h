#pragma once
// The gauge of a pose graph read from a file: relative measurements alone leave the whole graph free to move,
// so something must hold it. Without FIX lines the first pose is held by a tight prior (σ = 1e-6 on every
// tangent component) at its initial value; with FIX lines each named vertex is held that way instead.
// These priors are not part of the file's own edges: reports give chi2 over the file's edges only.

#include "semslam/io/PoseGraphFile.h"

namespace semslam {

inline constexpr double kAnchorSigma = 1e-6;

/// The priors that hold the gauge of `file` (see above), at the file's initial values.
FactorGraph anchorFactors(const PoseGraphFile& file, double sigma = kAnchorSigma);

}  // namespace semslam
