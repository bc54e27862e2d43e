#include "semslam/hybrid/HybridOptions.h"

#include <cmath>
#include <stdexcept>

#include "semslam/solve/BatchSmoother.h"

namespace semslam {

SmootherFactory defaultSmootherFactory() {
  return [] {
    OptimizerParams params;
    params.solver = SolverType::LevenbergMarquardt;
    params.maxIterations = 50;
    params.relativeDecreaseTolerance = 1e-9;
    return std::make_unique<BatchSmoother>(params);
  };
}

WeightMethod parseWeightMethod(const std::string& name) {
  if (name == "sampled") return WeightMethod::Sampled;
  if (name == "importance") return WeightMethod::Importance;
  if (name == "analytic") return WeightMethod::Analytic;
  throw std::invalid_argument("hybrid: unknown weight method '" + name + "' (sampled, importance or analytic)");
}

const char* weightMethodName(WeightMethod method) {
  switch (method) {
    case WeightMethod::Sampled: return "sampled";
    case WeightMethod::Importance: return "importance";
    case WeightMethod::Analytic: return "analytic";
  }
  return "sampled";
}

void HybridOptions::validate() const {
  if (samples < 2) throw std::invalid_argument("hybrid: at least 2 samples are needed");
  if (importanceIterations < 1) throw std::invalid_argument("hybrid: importance iterations must be >= 1");
  if (!std::isfinite(pruneRatio) || !std::isfinite(gateRatio)) throw std::invalid_argument("hybrid: ratios must be finite");
  if (!(jointCompatibility > 0.0 && jointCompatibility < 1.0)) {
    throw std::invalid_argument("hybrid: joint-compatibility confidence must be in (0, 1)");
  }
  if (maxComponents < 0) throw std::invalid_argument("hybrid: max components must be >= 0");
  if (maxCandidates < 1) throw std::invalid_argument("hybrid: max candidates must be >= 1");
  if (!(maxMemoryMiB > 0.0) || !std::isfinite(maxMemoryMiB)) {
    throw std::invalid_argument("hybrid: max memory must be a positive number of MiB");
  }
}

}  // namespace semslam
