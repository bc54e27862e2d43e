#pragma once
// Choosing a Smoother back end by name: what the methods take (a factory, since the hybrid belief makes one per
// component and the max-mixture pipeline one per run) and what the command line offers (`--smoother`).
//
//   incremental  IncrementalSmoother (iSAM2-style Bayes tree, docs/incremental-smoother.md): each update costs
//                what it touches; the default of the max-mixture pipeline; configured by IncrementalSmootherParams
//                (e.g. maxSwitchRounds, `semslam run --switch-rounds`);
//   batch        BatchSmoother: re-solves the whole graph at every update with the given optimiser settings.

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "semslam/solve/IncrementalSmootherParams.h"
#include "semslam/solve/Optimizer.h"
#include "semslam/solve/Smoother.h"

namespace semslam {

using SmootherFactory = std::function<std::unique_ptr<Smoother>()>;

enum class SmootherKind { Incremental, Batch };

/// "incremental" | "batch".
std::string smootherKindName(SmootherKind kind);
/// The inverse of smootherKindName; throws std::invalid_argument naming the valid choices.
SmootherKind parseSmootherKind(std::string_view name);

/// A factory of smoothers of `kind`; `batchParams` configure the batch smoother's optimiser, `incrementalParams`
/// the incremental smoother.
SmootherFactory smootherFactory(SmootherKind kind, const OptimizerParams& batchParams = {},
                                const IncrementalSmootherParams& incrementalParams = {});

}  // namespace semslam
