#pragma once
// HybridRunFolder: what `semslam run --method hybrid|hybrid-geometric` writes into its output folder:
//   metrics.json       evaluateRun + writeRunMetrics (the common schema, docs/metrics.md);
//   trajectory.tum     the heaviest final component's poses (and truth.tum, landmarks.csv, covariances.csv,
//                      associations.csv as io/RunFolder.h writes them);
//   hypotheses.jsonl   every step's belief (HypothesesJsonl.h).
// Returns the metrics written.

#include <string>

#include "semslam/eval/RunMetrics.h"
#include "semslam/hybrid/HybridRun.h"

namespace semslam {

RunMetrics writeHybridRunFolder(const std::string& directory, const MeasurementLog& log, const HybridRunOutput& run);

}  // namespace semslam
