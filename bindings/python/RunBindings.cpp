// semslam.run(method, log, **options): one estimation method over a measurement log, as `semslam run` does it.
//
// The keyword arguments are the run command's flags with `_` for `-` (apps/semslam/RunOptions.h: the same option
// binders parse them, so checks and defaults are the command's): `gate=0.95` is `--gate 0.95`, a flag such as
// `no_covariances=True` is `--no-covariances` (False leaves it out). An unknown keyword raises TypeError naming
// the accepted ones; a value the command would refuse raises ValueError with the command's message.
//
// The result holds, as numpy arrays and plain Python objects:
//   trajectory    N×3 (x, y, θ) or N×7 (x, y, z, qx, qy, qz, qw), one row per step, in time order
//   timestamps    N
//   landmarks     dict of arrays: id, position (M×2 or M×3), class (−1: no class belief), class_probability
//   associations  dict of arrays, one entry per detection: step, detection, landmark (NULL_HYPOTHESIS = −1),
//                 weight, truth (a landmark id, NOT_A_LANDMARK, UNKNOWN_TRUTH, or NO_TRUTH where the log has
//                 none), chi2 (NaN without a landmark)
//   hypotheses    hybrid methods: every step's belief, the dicts of hypotheses.jsonl; None otherwise
//   metrics       the dict of metrics.json, equal to the command's file
// The GIL is released while the method runs; after every step it is taken back to call `progress(done, total)`
// (a keyword of run() itself, not a flag) and to let Ctrl-C or an exception from the callback stop the run.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "../../apps/semslam/OptionValidators.h"
#include "../../apps/semslam/RunOptions.h"
#include "Bindings.h"
#include "PoseArrays.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/RunMetricsFile.h"

namespace semslam::python {
namespace {

constexpr int kNullHypothesis = -1;
constexpr int kNoTruth = -3;

/// semslam.RunResult (the file comment lists its members).
struct PythonRunResult {
  std::string method;
  py::object trajectory, timestamps, landmarks, associations, hypotheses, metrics, settings;
};

/// `--flag value...` for one keyword argument, checked against the options `command` knows.
void appendArgument(const CLI::App& command, const std::string& keyword, const py::handle& value,
                    std::vector<std::string>& argv) {
  std::string flag = "--" + keyword;
  for (char& c : flag) c = c == '_' ? '-' : c;
  const CLI::Option* option = command.get_option_no_throw(flag);
  if (option == nullptr || flag == "--method" || flag == "--help") {
    std::string accepted;
    for (const CLI::Option* known : command.get_options()) {
      if (known->get_lnames().empty()) continue;
      std::string name = known->get_lnames().front();
      if (name == "help" || name == "method") continue;
      for (char& c : name) c = c == '-' ? '_' : c;
      accepted += (accepted.empty() ? "" : ", ") + name;
    }
    throw py::type_error("run() got an unexpected keyword argument '" + keyword + "'; accepted: " + accepted);
  }
  if (option->get_expected_max() == 0) {  // a flag: takes no value
    if (!py::isinstance<py::bool_>(value)) throw py::type_error(keyword + ": a flag takes True or False");
    if (value.cast<bool>()) argv.push_back(flag);
    return;
  }
  if (py::isinstance<py::bool_>(value)) throw py::type_error(keyword + ": takes a value, not True or False");
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    // Only an option that takes several values takes a list; each value is one `--flag=value` token, so that no
    // value can pass for a flag of its own.
    if (option->get_expected_max() <= 1) throw py::type_error(keyword + ": takes one value, not a list");
    for (const py::handle item : value) argv.push_back(flag + "=" + py::str(item).cast<std::string>());
    return;
  }
  // str(float) is the shortest text that reads back exactly; `--flag=value` keeps a value such as "-1" a value.
  argv.push_back(flag + "=" + py::str(value).cast<std::string>());
}

cli::RunMethodArguments parseArguments(const std::string& method, const py::kwargs& options) {
  cli::RunMethodArguments arguments;
  CLI::App command("semslam.run");
  cli::addRunMethodOptions(&command, arguments);
  cli::requireDecimalIntegers(command);  // as the tool's main() does: "0467" is 467, never octal
  std::vector<std::string> argv = {"--method", method};
  for (const auto& [key, value] : options) appendArgument(command, key.cast<std::string>(), value, argv);
  std::reverse(argv.begin(), argv.end());  // CLI11 takes a vector of arguments last first
  try {
    command.parse(argv);
  } catch (const CLI::ParseError& error) {
    throw py::value_error(std::string("run(): ") + error.what());
  }
  return arguments;
}

py::dict landmarkArrays(const RunOutput& output) {
  const auto m = static_cast<Eigen::Index>(output.landmarks.size());
  Eigen::VectorXi ids(m), classes(m);
  Vector probabilities(m);
  Matrix positions(m, output.dimension);
  for (Eigen::Index i = 0; i < m; ++i) {
    const RunLandmark& landmark = output.landmarks[i];
    ids(i) = landmark.id;
    positions.row(i) = landmark.position.transpose();
    classes(i) = landmark.classIndex;
    probabilities(i) = landmark.classIndex >= 0 ? landmark.classProbability : std::numeric_limits<double>::quiet_NaN();
  }
  py::dict landmarks;
  landmarks["id"] = ids;
  landmarks["position"] = positions;
  landmarks["class"] = classes;
  landmarks["class_probability"] = probabilities;
  return landmarks;
}

py::dict associationArrays(const RunOutput& output) {
  const auto n = static_cast<Eigen::Index>(output.associations.size());
  Eigen::VectorXi steps(n), detections(n), landmarks(n), truths(n);
  Vector weights(n), chi2(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const AssociationRecord& record = output.associations[i];
    steps(i) = record.step;
    detections(i) = record.detection;
    landmarks(i) = record.landmark.value_or(kNullHypothesis);
    weights(i) = record.weight;
    truths(i) = record.truth.value_or(kNoTruth);
    chi2(i) = record.chi2.value_or(std::numeric_limits<double>::quiet_NaN());
  }
  py::dict associations;
  associations["step"] = steps;
  associations["detection"] = detections;
  associations["landmark"] = landmarks;
  associations["weight"] = weights;
  associations["truth"] = truths;
  associations["chi2"] = chi2;
  return associations;
}

PythonRunResult toPython(const MeasurementLog& log, const MethodRun& run) {
  const py::object loads = py::module_::import("json").attr("loads");
  PythonRunResult result;
  result.method = methodName(run.method);
  result.trajectory = poseArray(run.result.poses);
  result.timestamps = py::cast(stepTimes(log));
  result.landmarks = landmarkArrays(run.output);
  result.associations = associationArrays(run.output);
  result.metrics = loads(runMetricsToJson(run.evaluation.metrics));
  result.settings = loads(run.settings.dump());
  result.hypotheses = py::none();
  if (run.hypothesesJsonl) {
    std::ostringstream text;
    run.hypothesesJsonl->copyTo(text);
    py::list steps;
    std::istringstream lines(text.str());
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty()) steps.append(loads(line));
    }
    result.hypotheses = steps;
  }
  return result;
}

/// The run's progress, called after every step with the GIL taken back: the caller's `progress(done, total)` where
/// one was given, then Python's pending signals, so that Ctrl-C (KeyboardInterrupt) or an exception the callback
/// raises stops the run at the end of the current step and propagates. `callback` is borrowed: the caller's frame
/// holds it for the whole call (a raw pointer, because the std::function is copied without the GIL).
RunProgress progressReporter(PyObject* callback) {
  return [callback](int done, int total) {
    py::gil_scoped_acquire acquire;
    if (callback != Py_None) {
      const py::handle function(callback);
      function(done, total);
    }
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
}

PythonRunResult runOn(const MeasurementLog& log, const std::string& source, const std::string& method,
                      const py::object& progress, const py::kwargs& options) {
  const cli::RunMethodArguments arguments = parseArguments(method, options);
  if (!progress.is_none() && !PyCallable_Check(progress.ptr())) {
    throw py::type_error("progress: a callable progress(done, total), or None");
  }
  const RunProgress reporter = progressReporter(progress.ptr());
  MethodRun run;
  {
    py::gil_scoped_release release;
    run = cli::runFromArguments(log, arguments, source, reporter);
  }
  return toPython(log, run);
}

}  // namespace

void bindRun(py::module_& module) {
  module.attr("NULL_HYPOTHESIS") = kNullHypothesis;
  module.attr("NOT_A_LANDMARK") = kNotALandmark;
  module.attr("UNKNOWN_TRUTH") = kUnknownTruth;
  module.attr("NO_TRUTH") = kNoTruth;
  module.attr("METHODS") = methodNames();

  py::class_<PythonRunResult>(module, "RunResult", "What semslam.run returns (see its documentation).")
      .def_readonly("method", &PythonRunResult::method)
      .def_readonly("trajectory", &PythonRunResult::trajectory)
      .def_readonly("timestamps", &PythonRunResult::timestamps)
      .def_readonly("landmarks", &PythonRunResult::landmarks)
      .def_readonly("associations", &PythonRunResult::associations)
      .def_readonly("hypotheses", &PythonRunResult::hypotheses)
      .def_readonly("metrics", &PythonRunResult::metrics)
      .def_readonly("settings", &PythonRunResult::settings)
      .def("__repr__", [](const PythonRunResult& r) {
        return "<semslam.RunResult " + r.method + ": " + std::to_string(py::len(r.trajectory)) + " poses>";
      });

  module.def(
      "run",
      [](const std::string& method, const py::object& log, const py::object& progress, const py::kwargs& options) {
        if (py::isinstance<MeasurementLog>(log)) {
          return runOn(log.cast<const MeasurementLog&>(), "measurement log (in memory)", method, progress, options);
        }
        const std::string path = py::module_::import("os").attr("fsdecode")(log).cast<std::string>();
        MeasurementLog loaded;
        {
          py::gil_scoped_release release;
          loaded = readMeasurementLog(path);
        }
        return runOn(loaded, path, method, progress, options);
      },
      py::arg("method"), py::arg("log"), py::kw_only(), py::arg("progress") = py::none(),
      "Runs one method (known, ml, gpda, mm, mm-nh, hybrid, hybrid-geometric) over a measurement log (a path or "
      "a MeasurementLog); keyword arguments are `semslam run`'s flags with _ for -; progress(done, total), if "
      "given, is called after every step. Ctrl-C stops the run at the end of a step (KeyboardInterrupt).");
}

}  // namespace semslam::python
