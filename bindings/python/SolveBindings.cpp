// Solving: optimize() (batch Gauss-Newton or Levenberg-Marquardt), the BatchSmoother and the IncrementalSmoother
// behind one Smoother interface (update, estimate, joint_marginal, fork, converge), and Marginals of a graph at an
// estimate. Every call that solves releases the GIL, so other Python threads run meanwhile; the arguments are
// C++ objects held by the caller's Python references for the duration of the call.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <vector>

#include "Bindings.h"
#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/IncrementalSmoother.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/Optimizer.h"

namespace semslam::python {

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

  module.def("optimize", &optimize, py::arg("graph"), py::arg("initial"), py::arg("params") = OptimizerParams(),
             py::call_guard<py::gil_scoped_release>(),
             "Minimises the graph's objective from initial (Gauss-Newton by default).");

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

  py::class_<Smoother, std::shared_ptr<Smoother>>(module, "Smoother",
                                                  "A smoother: add factors and variables, re-solve, query.")
      .def("update",
           [](Smoother& smoother, const FactorGraph& factors, const Values& values,
              const std::vector<FactorIndex>& removed) { return smoother.update(factors, values, removed); },
           py::arg("new_factors") = FactorGraph(), py::arg("new_values") = Values(),
           py::arg("removed") = std::vector<FactorIndex>(), py::call_guard<py::gil_scoped_release>(),
           "Adds factors and values for new variables, removes the factors at `removed`, re-solves; returns the "
           "indices of the new factors.")
      .def("estimate", [](const Smoother& smoother) { return smoother.estimate(); }, "the current estimate")
      .def("joint_marginal",
           [](const Smoother& smoother, const std::vector<Key>& keys) {
             return smoother.jointMarginal(keys).covariance();
           },
           py::arg("keys"), py::call_guard<py::gil_scoped_release>(),
           "the joint covariance of keys at the estimate, blocks in the order given (tangent, translation first)")
      .def("marginal_covariance", &Smoother::marginalCovariance, py::arg("key"),
           py::call_guard<py::gil_scoped_release>())
      .def("factors", &Smoother::factors, "the current graph (removed factors left out)")
      .def("converge", &Smoother::converge, py::call_guard<py::gil_scoped_release>(),
           "iterates to the optimum of the current graph (the incremental smoother's final convergence)")
      .def("fork", [](const Smoother& smoother) { return std::shared_ptr<Smoother>(smoother.fork()); },
           "an independent copy (a hypothesis branch)")
      .def("memory_bytes", &Smoother::memoryBytes);

  py::class_<BatchSmoother, Smoother, std::shared_ptr<BatchSmoother>>(
      module, "BatchSmoother", "Re-solves the whole graph from the last estimate at every update.")
      .def(py::init<OptimizerParams>(), py::arg("params") = OptimizerParams());

  py::class_<IncrementalSmoother, Smoother, std::shared_ptr<IncrementalSmoother>>(
      module, "IncrementalSmoother", "iSAM2-class incremental smoothing on a Bayes tree (solve/IncrementalSmoother.h).")
      .def(py::init<IncrementalSmootherParams>(), py::arg("params") = IncrementalSmootherParams())
      .def("linearization_point", &IncrementalSmoother::linearizationPoint);

  py::class_<Marginals>(module, "Marginals", "Marginal covariances of a graph's variables at an estimate.")
      .def(py::init<const FactorGraph&, const Values&>(), py::arg("graph"), py::arg("values"),
           py::call_guard<py::gil_scoped_release>())
      .def("marginal_covariance", &Marginals::marginalCovariance, py::arg("key"))
      .def("joint_marginal",
           [](const Marginals& marginals, const std::vector<Key>& keys) {
             return marginals.jointMarginal(keys).covariance();
           },
           py::arg("keys"));
}

}  // namespace semslam::python
