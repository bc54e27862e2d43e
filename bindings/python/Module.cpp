// PYBIND11_MODULE(_semslam): the bindings of every layer (Bindings.h) and the translation of C++ exceptions.
//
//   semslam::InputError        → semslam.InputError (a ValueError) with .file, .line, .problem; str() is the
//                                C++ message "file:line: problem", as the command-line tool prints it
//   std::invalid_argument,
//   std::domain_error          → ValueError (pybind11's own translation, and ours for domain_error)
//   std::out_of_range          → IndexError (pybind11's; a missing key of Values raises KeyError)
//   anything else std::exception → RuntimeError (pybind11's default)

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

#include "Bindings.h"
#include "semslam/core/InputError.h"
#include "semslam/core/Version.h"

namespace py = pybind11;

PYBIND11_MODULE(_semslam, module) {
  module.doc() = "semslam: SLAM with ambiguous data association (the compiled core; import semslam)";
  module.attr("__version__") = std::string(semslam::version());

  static py::exception<semslam::InputError> inputError(module, "InputError", PyExc_ValueError);
  inputError.attr("__module__") = "semslam";
  // Local: this module's exceptions only, whatever other pybind11 modules the process has loaded.
  py::register_local_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const semslam::InputError& error) {
      py::object exception = py::reinterpret_borrow<py::object>(inputError.ptr())(error.what());
      exception.attr("file") = error.file();
      exception.attr("line") = error.line();
      exception.attr("problem") = error.problem();
      PyErr_SetObject(inputError.ptr(), exception.ptr());
    } catch (const std::domain_error& error) {
      PyErr_SetString(PyExc_ValueError, error.what());
    }
  });

  semslam::python::bindGeometry(module);
  semslam::python::bindGraph(module);
  semslam::python::bindSolve(module);
  semslam::python::bindFiles(module);
  semslam::python::bindEvaluation(module);
  semslam::python::bindRun(module);
}
