#pragma once
// HypothesesJsonl: hypotheses.jsonl, one JSON object per time step of a hybrid run (docs/hybrid-belief.md):
//   {"step": k, "components": [{"weight", "ancestor", "beta": [ids per detection of step k], "classes": [per
//     object, −1 collapsed], "pose": [x, y, θ] (2D) or [x, y, z, qx, qy, qz, qw] (3D), "covariance": [[3x3 or
//     6x6, right perturbation, translation first]]}, ...],
//    "association_marginal": [{"component", "weight"}, ...] (eq. 8, heaviest first),
//    "class_marginal": [[P(c_j = m)] per object] (eq. 7; [] without semantics),
//    "mixture": {"mean": [x, y(, z)], "covariance": [[2x2 or 3x3]]} (eq. 6, moments of the position),
//    "metrics": {"entropy", "det_cov", "err_wmax", "err_wavg", "ess", "assoc_weight_max", "components",
//                "histories"},
//    "report": {"parents", "candidates", "gated", "sampled", "gate_lost_mass", "pruned_mass", "survivors",
//               "capped_components", "memory_capped_components", "dropped_detections", "fell_back_to_linearized",
//               "analytic_total_variation", "max_relative_standard_error", "sampling_s", "step_s"}}
// A component's association history β_1:k is written once, as a tree: "beta" is its β_k (log ids, −1 a dropped
// detection) and "ancestor" the index of the component of line k − 1 it branched from (−1 at k = 0), so β_1:k is
// read by following ancestors back to the first line (python/hypotheses.py does). An association-marginal entry
// names the first component with its history. The file grows as O(steps × components), not O(steps² ×
// components) as whole histories per line would. Non-finite numbers are written as null. Written atomically.

#include <string>

#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/hybrid/HybridRun.h"
#include "semslam/io/SpooledText.h"

namespace semslam {

/// The JSON line of one step (no trailing newline); `metrics` are eval's HypothesisMetrics of that step's belief.
std::string hypothesesJsonLine(const HybridStepRecord& record, const HypothesisMetrics& metrics);

/// Writes `lines` (hypothesesJsonLine's, each ending in a newline, spooled as a run went) to `path`.
void writeHypothesesJsonl(const std::string& path, const SpooledText& lines);

}  // namespace semslam
