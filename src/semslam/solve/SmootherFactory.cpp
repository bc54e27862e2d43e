#include "semslam/solve/SmootherFactory.h"

#include <stdexcept>

#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/IncrementalSmoother.h"

namespace semslam {

std::string smootherKindName(SmootherKind kind) {
  return kind == SmootherKind::Incremental ? "incremental" : "batch";
}

SmootherKind parseSmootherKind(std::string_view name) {
  if (name == "incremental") return SmootherKind::Incremental;
  if (name == "batch") return SmootherKind::Batch;
  throw std::invalid_argument("unknown smoother '" + std::string(name) + "' (incremental, batch)");
}

SmootherFactory smootherFactory(SmootherKind kind, const OptimizerParams& batchParams,
                                const IncrementalSmootherParams& incrementalParams) {
  if (kind == SmootherKind::Incremental) {
    return [incrementalParams] { return std::make_unique<IncrementalSmoother>(incrementalParams); };
  }
  return [batchParams] { return std::make_unique<BatchSmoother>(batchParams); };
}

}  // namespace semslam
