#include "Datasets.h"

#include <exception>
#include <filesystem>
#include <map>
#include <memory>

#include "semslam/io/PoseGraphAnchor.h"

namespace semslam::bench {

const std::vector<Dataset>& datasets() {
  static const std::vector<Dataset> list = {
      {"manhattan", "vertigo/manhattan/originalDataset/g2o/manhattanOlson3500.g2o", GraphFormat::G2o, true},
      {"intel", "vertigo/intel/originalDataset/intel.g2o", GraphFormat::G2o, true},
      {"ring", "vertigo/ring/originalDataset/ring.g2o", GraphFormat::G2o, true},
      {"sphere2500", "vertigo/sphere2500/originalDataset/sphere2500.g2o", GraphFormat::G2o, false},
      {"city10000", "vertigo/city10000/originalDataset/city10000.g2o", GraphFormat::G2o, true},
      {"cityTrees10000", "isam/cityTrees10000.txt", GraphFormat::Isam, false},
  };
  return list;
}

std::string dataDirectory() { return SEMSLAM_BENCH_DATA_DIR; }

const PoseGraphProblem* loadProblem(const Dataset& dataset, std::string& error) {
  static std::map<std::string, std::unique_ptr<PoseGraphProblem>> cache;
  if (auto it = cache.find(dataset.name); it != cache.end()) return it->second.get();

  const std::filesystem::path path = std::filesystem::path(dataDirectory()) / dataset.relativePath;
  if (!std::filesystem::exists(path)) {
    error = "data file not found: " + path.string() + " (the benchmarks read ../shared/data)";
    return nullptr;
  }
  try {
    auto problem = std::make_unique<PoseGraphProblem>();
    problem->file = readPoseGraph(path.string(), dataset.format);
    problem->graph = problem->file.factors;
    problem->graph.add(anchorFactors(problem->file));
    return cache.emplace(dataset.name, std::move(problem)).first->second.get();
  } catch (const std::exception& e) {
    error = std::string("cannot read ") + path.string() + ": " + e.what();
    return nullptr;
  }
}

}  // namespace semslam::bench
