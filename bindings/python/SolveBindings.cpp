// Solving: optimize() (batch Gauss-Newton or Levenberg-Marquardt), the BatchSmoother and the IncrementalSmoother
// behind one Smoother interface (update, estimate, joint_marginal, fork, converge), and Marginals of a graph at an
// estimate.
//
// Threads. Every call that solves releases the GIL, so other Python threads run meanwhile. What it reads must then
// not change under it: a graph or values passed in are copied first (a graph holds shared pointers to immutable
// factors: the copy is cheap), and a smoother, which is not thread-safe (solve/Smoother.h), is held with a mutex
// (SmootherHandle) that each call takes after releasing the GIL, so two threads sharing one smoother take turns.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "Bindings.h"
#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/IncrementalSmoother.h"
#include "semslam/solve/LaplaceEvidence.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/Optimizer.h"

namespace semslam::python {
namespace {

/// A smoother as Python holds it: the C++ smoother and the mutex that serialises the calls of several Python
/// threads on it (see the file comment). The subclasses only say which smoother it is, for Python's types.
class SmootherHandle {
 public:
  explicit SmootherHandle(std::unique_ptr<Smoother> smoother) : smoother_(std::move(smoother)) {}
  virtual ~SmootherHandle() = default;

  /// f(smoother) with the GIL released and the smoother's mutex held.
  template <class Function>
  auto locked(Function&& f) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    return f(*smoother_);
  }

 private:
  std::unique_ptr<Smoother> smoother_;
  std::mutex mutex_;
};

class BatchSmootherHandle final : public SmootherHandle {
 public:
  using SmootherHandle::SmootherHandle;
  explicit BatchSmootherHandle(const OptimizerParams& params)
      : SmootherHandle(std::make_unique<BatchSmoother>(params)) {}
};

class IncrementalSmootherHandle final : public SmootherHandle {
 public:
  using SmootherHandle::SmootherHandle;
  explicit IncrementalSmootherHandle(const IncrementalSmootherParams& params)
      : SmootherHandle(std::make_unique<IncrementalSmoother>(params)) {}
};

/// A fork in a handle of its own kind.
std::shared_ptr<SmootherHandle> forkOf(SmootherHandle& handle) {
  std::unique_ptr<Smoother> fork = handle.locked([](Smoother& smoother) { return smoother.fork(); });
  if (dynamic_cast<IncrementalSmoother*>(fork.get()) != nullptr) {
    return std::make_shared<IncrementalSmootherHandle>(std::move(fork));
  }
  return std::make_shared<BatchSmootherHandle>(std::move(fork));
}

}  // namespace

void bindSolve(py::module_& module) {
  py::enum_<SolverType>(module, "Solver")
      .value("GAUSS_NEWTON", SolverType::GaussNewton)
      .value("LEVENBERG_MARQUARDT", SolverType::LevenbergMarquardt);

  py::class_<OptimizerParams>(module, "OptimizerParams", "Batch optimisation settings (solve/Optimizer.h).")
      .def(py::init<>())
      .def_readwrite("solver", &OptimizerParams::solver)
      .def_readwrite("max_iterations", &OptimizerParams::maxIterations)
      .def_readwrite("relative_decrease_tolerance", &OptimizerParams::relativeDecreaseTolerance)
      .def_readwrite("gradient_tolerance", &OptimizerParams::gradientTolerance)
      .def_readwrite("step_tolerance", &OptimizerParams::stepTolerance)
      .def_readwrite("initial_lambda", &OptimizerParams::initialLambda)
      .def_readwrite("max_lambda", &OptimizerParams::maxLambda)
      .def_readwrite("verbose", &OptimizerParams::verbose);

  py::class_<OptimizationResult>(module, "OptimizationResult")
      .def_readonly("values", &OptimizationResult::values)
      .def_readonly("initial_chi2", &OptimizationResult::initialChi2)
      .def_readonly("final_chi2", &OptimizationResult::finalChi2)
      .def_readonly("initial_gradient_norm", &OptimizationResult::initialGradientNorm)
      .def_readonly("final_gradient_norm", &OptimizationResult::finalGradientNorm)
      .def_readonly("iterations", &OptimizationResult::iterations)
      .def_readonly("stop_reason", &OptimizationResult::stopReason)
      .def_readonly("converged", &OptimizationResult::converged);

  module.def(
      "optimize",
      [](FactorGraph graph, Values initial, const OptimizerParams& params) {  // copies: see the file comment
        py::gil_scoped_release release;
        return optimize(graph, initial, params);
      },
      py::arg("graph"), py::arg("initial"), py::arg("params") = OptimizerParams(),
      "Minimises the graph's objective from initial (Gauss-Newton by default).");

  module.def(
      "laplace_evidence_score",
      [](FactorGraph graph, Values mode) {  // copies: see the file comment
        py::gil_scoped_release release;
        return laplaceEvidenceScore(graph, mode);
      },
      py::arg("graph"), py::arg("mode"),
      "-2 ln of the graph's evidence by Laplace's approximation at its mode (solve/LaplaceEvidence.h): "
      "sum of chi2 and normalisers at the mode, plus ln det of the Gauss-Newton information, minus N ln 2 pi.");

  py::class_<IncrementalSmootherParams>(module, "IncrementalSmootherParams",
                                        "Incremental smoother settings (solve/IncrementalSmootherParams.h).")
      .def(py::init<>())
      .def_readwrite("relinearize_threshold", &IncrementalSmootherParams::relinearizeThreshold)
      .def_readwrite("relinearize_skip", &IncrementalSmootherParams::relinearizeSkip)
      .def_readwrite("wildfire_threshold", &IncrementalSmootherParams::wildfireThreshold)
      .def_readwrite("reorder_fill_growth", &IncrementalSmootherParams::reorderFillGrowth)
      .def_readwrite("relaxed_clique_frontals", &IncrementalSmootherParams::relaxedCliqueFrontals)
      .def_readwrite("relaxed_clique_zeros", &IncrementalSmootherParams::relaxedCliqueZeros)
      .def_readwrite("max_switch_rounds", &IncrementalSmootherParams::maxSwitchRounds);

  py::class_<SmootherHandle, std::shared_ptr<SmootherHandle>>(
      module, "Smoother", "A smoother: add factors and variables, re-solve, query.")
      .def("update",
           [](SmootherHandle& handle, FactorGraph factors, Values values, const std::vector<FactorIndex>& removed) {
             return handle.locked([&](Smoother& smoother) { return smoother.update(factors, values, removed); });
           },
           py::arg("new_factors") = FactorGraph(), py::arg("new_values") = Values(),
           py::arg("removed") = std::vector<FactorIndex>(),
           "Adds factors and values for new variables, removes the factors at `removed`, re-solves; returns the "
           "indices of the new factors.")
      .def("estimate",
           [](SmootherHandle& handle) { return handle.locked([](Smoother& smoother) { return smoother.estimate(); }); },
           "the current estimate (a copy)")
      .def("joint_marginal",
           [](SmootherHandle& handle, const std::vector<Key>& keys) {
             return handle.locked([&](Smoother& smoother) { return smoother.jointMarginal(keys).covariance(); });
           },
           py::arg("keys"),
           "the joint covariance of keys at the estimate, blocks in the order given (tangent, translation first)")
      .def("marginal_covariance",
           [](SmootherHandle& handle, Key key) {
             return handle.locked([&](Smoother& smoother) { return smoother.marginalCovariance(key); });
           },
           py::arg("key"))
      .def("factors",
           [](SmootherHandle& handle) { return handle.locked([](Smoother& smoother) { return smoother.factors(); }); },
           "the current graph (removed factors left out)")
      .def("converge",
           [](SmootherHandle& handle) { handle.locked([](Smoother& smoother) { smoother.converge(); }); },
           "iterates to the optimum of the current graph (the incremental smoother's final convergence)")
      .def("fork", &forkOf, "an independent copy (a hypothesis branch)")
      .def("memory_bytes", [](SmootherHandle& handle) {
        return handle.locked([](Smoother& smoother) { return smoother.memoryBytes(); });
      });

  py::class_<BatchSmootherHandle, SmootherHandle, std::shared_ptr<BatchSmootherHandle>>(
      module, "BatchSmoother", "Re-solves the whole graph from the last estimate at every update.")
      .def(py::init<const OptimizerParams&>(), py::arg("params") = OptimizerParams());

  py::class_<IncrementalSmootherHandle, SmootherHandle, std::shared_ptr<IncrementalSmootherHandle>>(
      module, "IncrementalSmoother", "iSAM2-class incremental smoothing on a Bayes tree (solve/IncrementalSmoother.h).")
      .def(py::init<const IncrementalSmootherParams&>(), py::arg("params") = IncrementalSmootherParams());

  py::class_<Marginals>(module, "Marginals", "Marginal covariances of a graph's variables at an estimate.")
      .def(py::init([](FactorGraph graph, Values values) {  // copies: see the file comment
             py::gil_scoped_release release;
             return std::make_unique<Marginals>(graph, values);
           }),
           py::arg("graph"), py::arg("values"))
      .def("marginal_covariance", &Marginals::marginalCovariance, py::arg("key"))
      .def("joint_marginal",
           [](const Marginals& marginals, const std::vector<Key>& keys) {
             return marginals.jointMarginal(keys).covariance();
           },
           py::arg("keys"));
}

}  // namespace semslam::python
