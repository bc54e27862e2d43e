// Files: pose graphs (g2o, TORO, iSAM) with their gauge anchor, measurement logs (read, write, a few header
// fields), trajectories (TUM, KITTI, EuRoC) as numpy arrays. Every reader validates as the command-line tool does
// and raises semslam.InputError naming the file and line.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "Bindings.h"
#include "PoseArrays.h"
#include "semslam/eval/LandmarkMetrics.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/PoseGraphAnchor.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/TrajectoryFormat.h"
#include "semslam/io/TumFormat.h"
#include "semslam/models/Trajectory.h"

namespace semslam::python {

void bindFiles(py::module_& module) {
  // ---- pose graphs
  py::class_<PoseGraphFile>(module, "PoseGraph", "A pose-graph file: its edges, initial values, FIX lines.")
      .def_readonly("factors", &PoseGraphFile::factors)
      .def_readonly("initial", &PoseGraphFile::initial)
      .def_readonly("fixed", &PoseGraphFile::fixed)
      .def_readonly("equivalences", &PoseGraphFile::equivalences)
      .def_readonly("first_pose", &PoseGraphFile::firstPose)
      .def_readonly("dimension", &PoseGraphFile::dimension);
  module.def("read_pose_graph",
             [](const std::string& path, const std::string& format) {
               return readPoseGraph(path, parseGraphFormat(format));
             },
             py::arg("path"), py::arg("format") = "g2o", "format: g2o, toro or isam (EDGE2 differs between the last two)");
  module.def("anchor_factors", [](const PoseGraphFile& file, double sigma) { return anchorFactors(file, sigma); },
             py::arg("pose_graph"), py::arg("sigma") = kAnchorSigma,
             "the priors that hold the gauge, as `semslam optimize` adds them: the first pose (or every FIX vertex) "
             "at its initial value with σ = 1e-6");

  // ---- measurement logs
  py::class_<MeasurementLog>(module, "MeasurementLog",
                             "A measurement log (docs/measurement-log.md), as read and validated.")
      .def("__len__", [](const MeasurementLog& log) { return log.steps.size(); })
      .def_property_readonly("dimension", [](const MeasurementLog& log) { return log.header.dimension; })
      .def_property_readonly("classes", [](const MeasurementLog& log) { return log.header.classes; })
      .def_property_readonly("source", [](const MeasurementLog& log) { return log.header.source; })
      .def_property_readonly("timestamps", &stepTimes)
      .def_property_readonly("true_trajectory",
                             [](const MeasurementLog& log) -> py::object {
                               std::vector<Pose> poses;
                               for (const TimeStep& step : log.steps) {
                                 if (!step.truePose) return py::none();
                                 poses.push_back(*step.truePose);
                               }
                               return poseArray(poses);
                             },
                             "the true poses (N×3 or N×7, as RunResult.trajectory) where every step has one; "
                             "else None")
      .def_property_readonly("landmark_truth",
                             [](const MeasurementLog& log) -> py::object {
                               const auto& truth = log.header.landmarkTruth;
                               if (truth.empty()) return py::none();
                               const auto m = static_cast<Eigen::Index>(truth.size());
                               Eigen::VectorXi ids(m), classes(m);
                               Matrix positions(m, log.header.dimension);
                               for (Eigen::Index i = 0; i < m; ++i) {
                                 ids(i) = truth[i].id;
                                 classes(i) = truth[i].classIndex;
                                 positions.row(i) = landmarkPosition(truth[i].state).transpose();
                               }
                               py::dict landmarks;
                               landmarks["id"] = ids;
                               landmarks["position"] = positions;
                               landmarks["class"] = classes;
                               return landmarks;
                             },
                             "the true landmarks (dict of arrays: id, position M×2 or M×3, class; −1 unknown) "
                             "where the log has them; else None")
      .def_property_readonly("detections", [](const MeasurementLog& log) {
        std::vector<std::size_t> counts;
        for (const TimeStep& step : log.steps) counts.push_back(step.detections.size());
        return counts;
      }, "the number of detections of each step");
  module.def("read_log", &readMeasurementLog, py::arg("path"), py::call_guard<py::gil_scoped_release>());
  module.def("write_log", &writeMeasurementLog, py::arg("path"), py::arg("log"),
             py::call_guard<py::gil_scoped_release>(), "atomically, in deterministic bytes");

  // ---- trajectories
  py::class_<Trajectory>(module, "Trajectory",
                         "Timestamped SE3 poses (evo's PoseTrajectory3D): body in world, rotations as read.")
      .def(py::init([](const Vector& timestamps, const py::array_t<double>& poses) {
             return Trajectory(std::vector<double>(timestamps.data(), timestamps.data() + timestamps.size()),
                               posesFromArray(poses));
           }),
           py::arg("timestamps"), py::arg("poses"),
           "poses: N×3 (x, y, θ), N×7 (x, y, z, qx, qy, qz, qw) or N×4×4 homogeneous matrices")
      .def("__len__", &Trajectory::size)
      .def_property_readonly("timestamps",
                             [](const Trajectory& t) {
                               return Vector(Eigen::Map<const Vector>(t.timestamps().data(),
                                                                      static_cast<Eigen::Index>(t.size())));
                             })
      .def_property_readonly("has_timestamps", &Trajectory::hasTimestamps)
      .def_property_readonly("positions", [](const Trajectory& t) { return Matrix(t.positions().transpose()); },
                             "N×3")
      .def_property_readonly("xyz_quaternions", [](const Trajectory& t) { return xyzQuaternionArray(t.poses()); },
                             "N×7: x, y, z, qx, qy, qz, qw")
      .def_property_readonly("matrices", [](const Trajectory& t) { return matrixArray(t.poses()); }, "N×4×4")
      .def("path_length", &Trajectory::pathLength);
  module.def("read_trajectory",
             [](const std::string& path, const std::string& format) {
               return readTrajectory(path, parseTrajectoryFormat(format));
             },
             py::arg("path"), py::arg("format") = "tum", "format: tum, kitti or euroc");
  module.def("write_tum", &writeTumTrajectory, py::arg("path"), py::arg("trajectory"));
}

}  // namespace semslam::python
