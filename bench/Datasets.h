#pragma once
// The pose graphs the benchmarks solve, and a cache that reads each file once, outside every timed region.
//
// Files live in ../shared/data (never copied into the project). A benchmark whose file is absent reports
// that with state.SkipWithError and moves on.

#include <string>
#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"
#include "semslam/io/PoseGraphFile.h"

namespace semslam::bench {

struct Dataset {
  std::string name;          // short name used in benchmark names and the ratio table
  std::string relativePath;  // below the data directory
  GraphFormat format;
  bool planarPosesOnly;      // every variable an SE2 pose (the autodiff SE2 control applies)
};

/// manhattan, intel, ring, sphere2500, city10000, cityTrees10000, in that order.
const std::vector<Dataset>& datasets();

/// A problem ready to solve: the file's edges plus the first-pose anchor (PoseGraphAnchor.h).
struct PoseGraphProblem {
  PoseGraphFile file;
  FactorGraph graph;  // file.factors + anchorFactors(file)
};

/// The data directory (SEMSLAM_BENCH_DATA_DIR, set by CMake to ${PROJECT_SOURCE_DIR}/../shared/data).
std::string dataDirectory();

/// Reads `dataset` on first use and keeps it for the rest of the run. Returns nullptr and sets `error` if the
/// file is absent or unreadable.
const PoseGraphProblem* loadProblem(const Dataset& dataset, std::string& error);

}  // namespace semslam::bench
