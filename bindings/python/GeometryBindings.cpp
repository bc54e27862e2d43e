// SO2, SE2, SO3, SE3 (geometry/): construction, compose (also `*`), inverse, between, exp/log, retract and
// local_coordinates (right perturbation, translation first, as the C++ classes), matrix(), and the point maps.
// Vectors and matrices are numpy arrays.

#include <pybind11/eigen.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "Bindings.h"
#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"
#include "semslam/geometry/SO2.h"
#include "semslam/geometry/SO3.h"

namespace semslam::python {
namespace {

template <class Group, class Class>
void bindGroupOperations(Class& group) {
  group.def("compose", [](const Group& a, const Group& b) { return a.compose(b); }, py::arg("other"), "self · other")
      .def("__mul__", [](const Group& a, const Group& b) { return a.compose(b); })
      .def("inverse", [](const Group& a) { return a.inverse(); })
      .def("between", [](const Group& a, const Group& b) { return a.between(b); }, py::arg("other"),
           "self⁻¹ · other")
      .def("log", [](const Group& a) { return Group::Log(a); }, "the tangent vector ξ with exp(ξ) = self")
      .def_static("exp", [](const typename Group::TangentVector& xi) { return Group::Exp(xi); }, py::arg("xi"))
      .def("retract", [](const Group& a, const typename Group::TangentVector& delta) { return a.retract(delta); },
           py::arg("delta"), "self · exp(delta)")
      .def("local_coordinates", [](const Group& a, const Group& b) { return a.localCoordinates(b); },
           py::arg("other"), "log(self⁻¹ · other)")
      .def("matrix", [](const Group& a) { return a.matrix(); })
      .def("adjoint", [](const Group& a) { return a.adjoint(); })
      .def("equals", [](const Group& a, const Group& b, double tol) { return a.equals(b, tol); }, py::arg("other"),
           py::arg("tol") = 1e-9)
      .def_property_readonly_static("dimension", [](py::object) { return Group::kDim; });
}

/// A rotation from a matrix a user passed: finite, or ValueError.
SO3 rotationFrom(const Matrix3& R) {
  if (!R.allFinite()) throw std::invalid_argument("a rotation matrix must be finite");
  return SO3::nearest(R);
}

/// A pose from a 4×4 homogeneous matrix: finite, bottom row [0 0 0 1], or ValueError.
SE3 poseFrom(const Matrix4& T) {
  if (!T.allFinite()) throw std::invalid_argument("a pose matrix must be finite");
  if ((T.bottomRows<1>() - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9) {
    throw std::invalid_argument("a pose matrix has the bottom row [0, 0, 0, 1]");
  }
  return SE3(rotationFrom(T.topLeftCorner<3, 3>()), T.topRightCorner<3, 1>());
}

std::string formatted(const Eigen::MatrixXd& values) {
  std::ostringstream text;
  text.precision(17);
  for (Eigen::Index i = 0; i < values.size(); ++i) text << (i ? ", " : "") << values(i);
  return text.str();
}

}  // namespace

void bindGeometry(py::module_& module) {
  py::class_<SO2> so2(module, "SO2", "A planar rotation by θ (radians).");
  so2.def(py::init<>())
      .def(py::init<double>(), py::arg("theta"))
      .def("theta", &SO2::theta)
      .def("rotate", [](const SO2& R, const Point2& p) { return R.rotate(p); }, py::arg("point"))
      .def("unrotate", [](const SO2& R, const Point2& p) { return R.unrotate(p); }, py::arg("point"))
      .def("__repr__", [](const SO2& R) { return "SO2(" + formatted(Vector1(R.theta())) + ")"; });
  bindGroupOperations<SO2>(so2);

  py::class_<SE2> se2(module, "SE2", "A planar pose (x, y, θ): rotation θ about z, then translation (x, y).");
  se2.def(py::init<>())
      .def(py::init<double, double, double>(), py::arg("x"), py::arg("y"), py::arg("theta"))
      .def(py::init<const SO2&, const Point2&>(), py::arg("rotation"), py::arg("translation"))
      .def("x", &SE2::x)
      .def("y", &SE2::y)
      .def("theta", &SE2::theta)
      .def("translation", [](const SE2& T) { return Point2(T.translation()); })
      .def("rotation", [](const SE2& T) { return T.rotation(); })
      .def("vector", [](const SE2& T) { return Vector3(T.x(), T.y(), T.theta()); }, "[x, y, θ]")
      .def("transform_from", [](const SE2& T, const Point2& p) { return T.transformFrom(p); }, py::arg("point"),
           "a point of the pose's frame in the world: R p + t")
      .def("transform_to", [](const SE2& T, const Point2& p) { return T.transformTo(p); }, py::arg("point"),
           "a world point in the pose's frame: Rᵀ (p − t)")
      .def("__repr__", [](const SE2& T) { return "SE2(" + formatted(Vector3(T.x(), T.y(), T.theta())) + ")"; });
  bindGroupOperations<SE2>(se2);

  py::class_<SO3> so3(module, "SO3", "A rotation in 3D.");
  so3.def(py::init<>())
      .def(py::init(&rotationFrom), py::arg("matrix"), "the rotation nearest to a 3×3 matrix (its polar factor)")
      .def_static("from_quaternion",
                  [](double qx, double qy, double qz, double qw) {
                    return SO3::fromQuaternion(Eigen::Quaterniond(qw, qx, qy, qz));
                  },
                  py::arg("qx"), py::arg("qy"), py::arg("qz"), py::arg("qw"), "normalised first")
      .def_static("from_axis_angle", &SO3::fromAxisAngle, py::arg("axis"), py::arg("angle"))
      .def("quaternion",
           [](const SO3& R) {
             const Eigen::Quaterniond q = R.toQuaternion();
             return Vector4(q.x(), q.y(), q.z(), q.w());
           },
           "[qx, qy, qz, qw]")
      .def("rotate", [](const SO3& R, const Point3& p) { return R.rotate(p); }, py::arg("point"))
      .def("unrotate", [](const SO3& R, const Point3& p) { return R.unrotate(p); }, py::arg("point"))
      .def("__repr__", [](const SO3& R) { return "SO3(log=[" + formatted(SO3::Log(R)) + "])"; });
  bindGroupOperations<SO3>(so3);

  py::class_<SE3> se3(module, "SE3", "A pose in 3D: rotation R, then translation t (x_world = R x_body + t).");
  se3.def(py::init<>())
      .def(py::init<const SO3&, const Point3&>(), py::arg("rotation"), py::arg("translation"))
      .def(py::init(&poseFrom), py::arg("matrix"), "from a 4×4 homogeneous matrix (the rotation block projected onto SO3)")
      .def("translation", [](const SE3& T) { return Point3(T.translation()); })
      .def("rotation", [](const SE3& T) { return T.rotation(); })
      .def("transform_from", [](const SE3& T, const Point3& p) { return T.transformFrom(p); }, py::arg("point"))
      .def("transform_to", [](const SE3& T, const Point3& p) { return T.transformTo(p); }, py::arg("point"))
      .def("__repr__", [](const SE3& T) {
        const Eigen::Quaterniond q = T.rotation().toQuaternion();
        return "SE3(t=[" + formatted(T.translation()) + "], q=[" + formatted(Vector4(q.x(), q.y(), q.z(), q.w())) +
               "])";
      });
  bindGroupOperations<SE3>(se3);
}

}  // namespace semslam::python
