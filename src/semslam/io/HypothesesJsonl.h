#pragma once
// HypothesesJsonl: hypotheses.jsonl, one JSON object per time step of a hybrid run (docs/hybrid-belief.md):
//   {"step": k, "components": [{"weight", "associations": [[ids per detection] per step], "classes": [per object,
//     −1 collapsed], "pose": [x, y, θ], "covariance": [[3x3]]}, ...],
//    "association_marginal": [{"associations", "weight"}, ...] (eq. 8, heaviest first),
//    "class_marginal": [[P(c_j = m)] per object] (eq. 7; [] without semantics),
//    "mixture": {"mean": [x, y], "covariance": [[2x2]]} (eq. 6, moments of the position),
//    "metrics": {"entropy", "det_cov", "err_wmax", "err_wavg", "ess", "assoc_weight_max", "components",
//                "histories"},
//    "report": {"parents", "candidates", "gated", "sampled", "gate_lost_mass", "pruned_mass", "survivors",
//               "dropped_detections", "fell_back_to_linearized", "analytic_total_variation",
//               "max_relative_standard_error", "sampling_s", "step_s"}}
// Non-finite numbers are written as null. Written atomically.

#include <string>
#include <vector>

#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/hybrid/HybridRun.h"

namespace semslam {

/// The JSON line of one step (no trailing newline); `metrics` are eval's HypothesisMetrics of that step's belief.
std::string hypothesesJsonLine(const HybridStepRecord& record, const HypothesisMetrics& metrics);

/// One line per step; `metrics` holds one record per step.
void writeHypothesesJsonl(const std::string& path, const std::vector<HybridStepRecord>& steps,
                          const std::vector<HypothesisMetrics>& metrics);

}  // namespace semslam
