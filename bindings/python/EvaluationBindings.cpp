// ate() and rpe(): evo_ape and evo_rpe on two trajectories (eval/TrajectoryEvaluation.h), returning evo's
// statistics dict {max, mean, median, min, rmse, sse, std}; `errors=True` adds the per-pose (per-pair) errors.
// Option names and values are `semslam eval`'s (and evo's): align none|se3|sim3|scale|origin, relation
// trans_part|angle_deg|angle_rad|rot_part|full, delta_unit frames|m.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "Bindings.h"
#include "semslam/eval/TrajectoryEvaluation.h"

namespace semslam::python {
namespace {

py::dict statisticsDict(const EvaluationResult& result, bool withErrors) {
  const ErrorStatistics& s = result.statistics;
  py::dict statistics;
  statistics["max"] = s.max;
  statistics["mean"] = s.mean;
  statistics["median"] = s.median;
  statistics["min"] = s.min;
  statistics["rmse"] = s.rmse;
  statistics["sse"] = s.sse;
  statistics["std"] = s.std;
  if (withErrors) statistics["errors"] = py::array_t<double>(py::cast(result.errors));
  return statistics;
}

}  // namespace

void bindEvaluation(py::module_& module) {
  module.def(
      "ate",
      [](const Trajectory& estimate, const Trajectory& reference, const std::string& align, const std::string& relation,
         double maxTimeDifference, double timeOffset, bool errors) {
        EvaluationOptions options;
        options.alignment = parseAlignmentMode(align);
        options.relation = parsePoseRelation(relation);
        options.maxTimeDifference = maxTimeDifference;
        options.timeOffset = timeOffset;
        return statisticsDict(evaluateAbsolutePoseError(reference, estimate, options), errors);
      },
      py::arg("estimate"), py::arg("reference"), py::kw_only(), py::arg("align") = "none",
      py::arg("relation") = "trans_part", py::arg("t_max_diff") = 0.01, py::arg("t_offset") = 0.0,
      py::arg("errors") = false, "The absolute pose error (evo_ape): evo's statistics dict.");
  module.def(
      "rpe",
      [](const Trajectory& estimate, const Trajectory& reference, const std::string& align, const std::string& relation,
         double delta, const std::string& deltaUnit, bool allPairs, double deltaTolerance, bool pairsFromReference,
         double maxTimeDifference, double timeOffset, bool errors) {
        EvaluationOptions options;
        options.alignment = parseAlignmentMode(align);
        options.relation = parsePoseRelation(relation);
        options.delta = delta;
        options.deltaUnit = parseDeltaUnit(deltaUnit);
        options.allPairs = allPairs;
        options.relativeDeltaTolerance = deltaTolerance;
        options.pairsFromReference = pairsFromReference;
        options.maxTimeDifference = maxTimeDifference;
        options.timeOffset = timeOffset;
        return statisticsDict(evaluateRelativePoseError(reference, estimate, options), errors);
      },
      py::arg("estimate"), py::arg("reference"), py::kw_only(), py::arg("align") = "none",
      py::arg("relation") = "trans_part", py::arg("delta") = 1.0, py::arg("delta_unit") = "frames",
      py::arg("all_pairs") = false, py::arg("delta_tol") = 0.1, py::arg("pairs_from_reference") = false,
      py::arg("t_max_diff") = 0.01, py::arg("t_offset") = 0.0, py::arg("errors") = false,
      "The relative pose error (evo_rpe): evo's statistics dict.");
}

}  // namespace semslam::python
