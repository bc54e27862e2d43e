// Keys (pose_key, landmark_key, Symbol strings), Values (one value per key: a numpy 2- or 3-vector for a point,
// or SO2/SE2/SO3/SE3), NoiseModel, the library's factors and the FactorGraph.
//
// Factors and noise models are immutable once built; C++ holds them as shared_ptr<const T>, Python through
// shared_ptr<T> (pybind11 has no const holders), converted at this boundary only.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "Bindings.h"
#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/MaxMixtureFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RangeBearingElevationFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Key.h"
#include "semslam/graph/NoiseModel.h"
#include "semslam/graph/RobustKernel.h"
#include "semslam/graph/Values.h"

namespace semslam::python {
namespace {

using MutableNoiseModel = std::shared_ptr<NoiseModel>;
using MutableFactor = std::shared_ptr<Factor>;

MutableNoiseModel mutableNoise(const SharedNoiseModel& model) { return std::const_pointer_cast<NoiseModel>(model); }

/// A numpy vector as the point it stands for: 2 or 3 numbers.
Value pointValue(const Vector& point) {
  if (point.size() == 2) return Point2(point);
  if (point.size() == 3) return Point3(point);
  throw std::invalid_argument("a point value has 2 or 3 coordinates, got " + std::to_string(point.size()));
}

py::object toPython(const Value& value) {
  return std::visit(
      [](const auto& v) -> py::object {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Point2> || std::is_same_v<T, Point3>) {
          return py::cast(Vector(v));
        } else {
          return py::cast(v);
        }
      },
      value);
}

/// The value at `key`, as toPython gives it; a missing key raises KeyError, as a Python mapping does.
py::object valueAt(const Values& values, Key key) {
  if (!values.exists(key)) throw py::key_error("no variable " + keyToString(key));
  return toPython(values.value(key));
}

/// A factor type of the library with its constructor (`init`: a py::init of Python arguments) and its accessors:
/// noise_model(), and measured() (prior() for a prior factor).
template <class FactorType, class Init, class... Extra>
void bindMeasurementFactor(py::module_& module, const char* name, const char* doc, Init&& init, Extra&&... extra) {
  py::class_<FactorType, Factor, std::shared_ptr<FactorType>> factor(module, name, doc);
  factor.def(std::forward<Init>(init), std::forward<Extra>(extra)...)
      .def("noise_model", [](const FactorType& f) { return mutableNoise(f.noiseModel()); });
  if constexpr (requires(const FactorType& f) { f.prior(); }) {
    factor.def("prior", [](const FactorType& f) { return f.prior(); });
  } else {
    factor.def("measured", [](const FactorType& f) { return f.measured(); });
  }
}

/// Prior and between factors on one value type T.
template <class T>
void bindPriorAndBetween(py::module_& module, const std::string& typeName) {
  bindMeasurementFactor<PriorFactor<T>>(
      module, ("PriorFactor" + typeName).c_str(), ("A Gaussian prior on one " + typeName + " variable.").c_str(),
      py::init([](Key key, const T& prior, const MutableNoiseModel& noise) {
        return std::make_shared<PriorFactor<T>>(key, prior, noise);
      }),
      py::arg("key"), py::arg("prior"), py::arg("noise_model"));
  bindMeasurementFactor<BetweenFactor<T>>(
      module, ("BetweenFactor" + typeName).c_str(),
      ("A measured relative " + typeName + " z between x_i and x_j (odometry, loop closures).").c_str(),
      py::init([](Key i, Key j, const T& measured, const MutableNoiseModel& noise) {
        return std::make_shared<BetweenFactor<T>>(i, j, measured, noise);
      }),
      py::arg("key_i"), py::arg("key_j"), py::arg("measured"), py::arg("noise_model"));
}

}  // namespace

void bindGraph(py::module_& module) {
  // ---- keys
  module.def("pose_key", [](std::uint64_t i) { return poseKey(i); }, py::arg("index"), "the key x<index>");
  module.def("landmark_key", [](std::uint64_t j) { return landmarkKey(j); }, py::arg("index"), "the key l<index>");
  module.def("key_to_string", &keyToString, py::arg("key"), "'x12', 'l3', or the plain number");
  module.def("key_from_string", &keyFromString, py::arg("text"));

  // ---- values
  py::class_<Values>(module, "Values", "The estimate of every variable, by key (iterated in increasing key order).")
      .def(py::init<>())
      // The group overloads first: pybind11 tries overloads in order, and a pose is inserted far more often than a
      // point (this order is what keeps building a graph in a Python loop cheap; bench/python_overhead.py).
      .def("insert", [](Values& v, Key key, const SE2& x) { v.insert(key, x); }, py::arg("key"), py::arg("value"))
      .def("insert", [](Values& v, Key key, const SE3& x) { v.insert(key, x); }, py::arg("key"), py::arg("value"))
      .def("insert", [](Values& v, Key key, const SO2& x) { v.insert(key, x); }, py::arg("key"), py::arg("value"))
      .def("insert", [](Values& v, Key key, const SO3& x) { v.insert(key, x); }, py::arg("key"), py::arg("value"))
      .def("insert", [](Values& v, Key key, const Vector& point) { v.insert(key, pointValue(point)); },
           py::arg("key"), py::arg("point"))
      .def("update", [](Values& v, Key key, const SE2& x) { v.update(key, x); }, py::arg("key"), py::arg("value"))
      .def("update", [](Values& v, Key key, const SE3& x) { v.update(key, x); }, py::arg("key"), py::arg("value"))
      .def("update", [](Values& v, Key key, const Vector& point) { v.update(key, pointValue(point)); },
           py::arg("key"), py::arg("point"))
      .def("at", &valueAt, py::arg("key"), "the value at key: SO2/SE2/SO3/SE3, or a numpy vector for a point")
      .def("__getitem__", &valueAt)
      .def("__iter__", [](const Values& v) { return py::iter(py::cast(v.keys())); }, "the keys, in increasing order")
      .def("items", [](const Values& v) {
        py::list items;
        for (Key key : v.keys()) items.append(py::make_tuple(key, valueAt(v, key)));
        return items;
      }, "(key, value) pairs, keys in increasing order")
      .def("erase", &Values::erase, py::arg("key"))
      .def("exists", &Values::exists, py::arg("key"))
      .def("__contains__", &Values::exists)
      .def("__len__", &Values::size)
      .def("keys", &Values::keys)
      .def("dimension", &Values::totalDimension, "the sum of the tangent dimensions");

  // ---- noise models and robust kernels
  py::class_<RobustKernel, std::shared_ptr<RobustKernel>>(module, "RobustKernel")
      .def("cost", &RobustKernel::cost, py::arg("squared_error"))
      .def("weight", &RobustKernel::weight, py::arg("squared_error"))
      .def("name", &RobustKernel::name);
  py::class_<HuberKernel, RobustKernel, std::shared_ptr<HuberKernel>>(module, "HuberKernel")
      .def(py::init<double>(), py::arg("threshold"));
  py::class_<CauchyKernel, RobustKernel, std::shared_ptr<CauchyKernel>>(module, "CauchyKernel")
      .def(py::init<double>(), py::arg("scale"));

  py::class_<NoiseModel, MutableNoiseModel>(module, "NoiseModel",
                                            "A Gaussian noise model held as its square-root information R "
                                            "(RᵀR = Σ⁻¹); an optional robust kernel.")
      .def_static("from_sigmas", [](const Vector& sigmas) { return mutableNoise(NoiseModel::fromSigmas(sigmas)); },
                  py::arg("sigmas"))
      .def_static("from_covariance",
                  [](const Eigen::Ref<const Matrix>& covariance) {
                    return mutableNoise(NoiseModel::fromCovariance(covariance));
                  },
                  py::arg("covariance"))
      .def_static("from_information",
                  [](const Eigen::Ref<const Matrix>& information) {
                    return mutableNoise(NoiseModel::fromInformation(information));
                  },
                  py::arg("information"))
      .def_static("isotropic",
                  [](int dimension, double sigma) { return mutableNoise(NoiseModel::isotropic(dimension, sigma)); },
                  py::arg("dimension"), py::arg("sigma"))
      .def("with_robust_kernel",
           [](const NoiseModel& model, std::shared_ptr<RobustKernel> kernel) {
             return mutableNoise(model.withRobustKernel(std::move(kernel)));
           },
           py::arg("kernel"))
      .def("dimension", &NoiseModel::dimension)
      .def("covariance", &NoiseModel::covariance)
      .def("information", &NoiseModel::information)
      .def("sqrt_information", &NoiseModel::sqrtInformation);

  // ---- factors
  py::class_<Factor, MutableFactor>(module, "Factor", "A factor of the graph (abstract).")
      .def("keys", &Factor::keys)
      .def("error_dimension", &Factor::errorDimension)
      .def("chi2", &Factor::chi2, py::arg("values"), "its squared whitened error at values (robust cost if any)")
      .def("active_component", &Factor::activeComponent, py::arg("values"),
           "a mixture's chosen component at values; -1 for other factors");

  bindPriorAndBetween<SE2>(module, "SE2");
  bindPriorAndBetween<SE3>(module, "SE3");
  bindPriorAndBetween<Point2>(module, "Point2");
  bindPriorAndBetween<Point3>(module, "Point3");
  bindMeasurementFactor<RangeBearingFactor<Point2>>(
      module, "RangeBearingFactor", "Range and bearing [r, φ] of a point landmark from an SE2 pose.",
      py::init([](Key pose, Key landmark, const Vector2& measured, const MutableNoiseModel& noise) {
        return std::make_shared<RangeBearingFactor<Point2>>(pose, landmark, measured, noise);
      }),
      py::arg("pose_key"), py::arg("landmark_key"), py::arg("measured"), py::arg("noise_model"));
  bindMeasurementFactor<RangeBearingElevationFactor<Point3>>(
      module, "RangeBearingElevationFactor",
      "Range, bearing and elevation [r, φ, ψ] of a point landmark from an SE3 pose.",
      py::init([](Key pose, Key landmark, const Vector3& measured, const MutableNoiseModel& noise) {
        return std::make_shared<RangeBearingElevationFactor<Point3>>(pose, landmark, measured, noise);
      }),
      py::arg("pose_key"), py::arg("landmark_key"), py::arg("measured"), py::arg("noise_model"));
  bindMeasurementFactor<RelativePointFactor<SE2, Point2>>(
      module, "RelativePointFactor2", "A point landmark's position measured in the frame of an SE2 pose.",
      py::init([](Key pose, Key landmark, const Point2& measured, const MutableNoiseModel& noise) {
        return std::make_shared<RelativePointFactor<SE2, Point2>>(pose, landmark, measured, noise);
      }),
      py::arg("pose_key"), py::arg("landmark_key"), py::arg("measured"), py::arg("noise_model"));
  bindMeasurementFactor<RelativePointFactor<SE3, Point3>>(
      module, "RelativePointFactor3", "A point landmark's position measured in the frame of an SE3 pose.",
      py::init([](Key pose, Key landmark, const Point3& measured, const MutableNoiseModel& noise) {
        return std::make_shared<RelativePointFactor<SE3, Point3>>(pose, landmark, measured, noise);
      }),
      py::arg("pose_key"), py::arg("landmark_key"), py::arg("measured"), py::arg("noise_model"));
  py::class_<MaxMixtureFactor, Factor, std::shared_ptr<MaxMixtureFactor>>(
      module, "MaxMixtureFactor",
      "A max-mixture of factors (paper B): at any estimate the component of least −log(w_i N_i) is active.")
      .def(py::init([](const std::vector<std::pair<MutableFactor, double>>& components) {
             std::vector<MaxMixtureFactor::Component> parts;
             for (const auto& [factor, weight] : components) parts.push_back({factor, weight, std::nullopt});
             return std::make_shared<MaxMixtureFactor>(std::move(parts));
           }),
           py::arg("components"), "components: a list of (factor, weight) pairs")
      .def("components", [](const MaxMixtureFactor& mixture) {
        std::vector<std::pair<MutableFactor, double>> parts;
        for (const auto& c : mixture.components()) parts.emplace_back(std::const_pointer_cast<Factor>(c.factor), c.weight);
        return parts;
      });

  // ---- the graph
  py::class_<FactorGraph>(module, "FactorGraph", "An ordered list of factors.")
      .def(py::init<>())
      .def("add", [](FactorGraph& graph, const MutableFactor& factor) { graph.add(factor); }, py::arg("factor"))
      .def("add_graph", [](FactorGraph& graph, const FactorGraph& other) { graph.add(other); }, py::arg("graph"))
      .def("__len__", &FactorGraph::size)
      .def("__getitem__",
           [](const FactorGraph& graph, std::size_t i) {
             if (i >= graph.size()) throw py::index_error("factor index " + std::to_string(i) + " out of range");
             return std::const_pointer_cast<Factor>(graph[i]);
           })
      .def("chi2", &FactorGraph::chi2, py::arg("values"), "the sum of the factors' chi2 at values")
      .def("keys", &FactorGraph::keys);
}

}  // namespace semslam::python
