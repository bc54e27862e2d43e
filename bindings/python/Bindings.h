#pragma once
// The Python module `_semslam` (pybind11), bound one layer per file; `semslam/__init__.py` is the pure package
// around it. The layer is thin on purpose: every function forwards to the C++ library, converting Eigen ↔ numpy
// through pybind11/eigen.h (whole arrays, no per-element Python loops) and C++ exceptions to Python ones
// (Module.cpp). No estimation logic lives here.

#include <pybind11/pybind11.h>

namespace semslam::python {

namespace py = pybind11;

void bindGeometry(py::module_& module);    // GeometryBindings.cpp: SO2, SE2, SO3, SE3
void bindGraph(py::module_& module);       // GraphBindings.cpp: keys, Values, NoiseModel, factors, FactorGraph
void bindSolve(py::module_& module);       // SolveBindings.cpp: optimize, BatchSmoother, IncrementalSmoother, Marginals
void bindFiles(py::module_& module);       // FileBindings.cpp: pose graphs, measurement logs, trajectories
void bindEvaluation(py::module_& module);  // EvaluationBindings.cpp: ate, rpe
void bindRun(py::module_& module);         // RunBindings.cpp: run(method, log, **options)

}  // namespace semslam::python
