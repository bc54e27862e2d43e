#pragma once
// The measurement log: what every method consumes and every converter and simulator produces.
//
// A log is one header (the problem: dimension, classes, semantic model, sensor, priors, optional landmark ground
// truth) and one record per time step (odometry since the previous step, the step's detections, optional ground
// truth). The file format (JSON lines, versioned) is specified in docs/measurement-log.md and read and written by
// io/MeasurementLogFile.h; this header is the in-memory form.
//
// Conventions: poses are SE2 (dimension 2) or SE3 (dimension 3); covariances are in the tangent of the right
// perturbation, translation first; angles in radians, lengths in metres, time in seconds. Landmark ids are the
// log's own non-negative integers; a detection's true landmark id is kNotALandmark for clutter (false positives,
// other robots, unknown markers), or kUnknownTruth where the dataset's ground truth cannot say which (docs/
// measurement-log.md, "Detections": e.g. a KITTI detection inside a DontCare region, or of an object that moves a
// little); absent means the log carries no truth for it. Metrics score only a landmark id or kNotALandmark
// (scoredTruth below).

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"

namespace semslam {

using Pose = std::variant<SE2, SE3>;
/// A landmark is a point (Point2/Point3) or, for objects with an orientation, a pose (SE2/SE3).
using LandmarkState = std::variant<Point2, Point3, SE2, SE3>;

/// Truth of clutter: a false positive, another robot, a moving object (file: "not-a-landmark").
inline constexpr int kNotALandmark = -1;
/// Truth that the dataset's labels cannot decide (file: "unknown", version 2): neither a landmark nor clutter for
/// scoring; every metric leaves such a detection out, exactly as one without truth (docs/metrics.md).
inline constexpr int kUnknownTruth = -2;

/// What a detection's geometric part measures (and hence its length).
enum class SensorKind {
  RangeBearing,           // 2D: (range, bearing)
  RangeBearingElevation,  // 3D: (range, bearing, elevation)
  RelativePosition,       // the landmark's position in the sensor frame: 2 or 3 numbers
  RelativePose,           // the landmark's pose in the sensor frame: SE2 (x, y, θ) or SE3 (x, y, z, qx, qy, qz, qw)
};

/// What a detection's semantic part is.
enum class SemanticKind {
  None,           // geometry only
  Label,          // one class index in [0, classes)
  Probabilities,  // a class-probability vector (non-negative, sums to one)
  Scores,         // raw classifier outputs (paper A's Gaussian classifier model; may leave the simplex)
};

/// Which classifier model explains the semantic part.
struct ClassifierModelSpec {
  enum class Kind { None, Categorical, ViewpointGaussian } kind = Kind::None;
  double misclassification = 0.0;  // Categorical: P(wrong class) p, spread evenly over the other classes
  double alpha = 0.25;             // ViewpointGaussian (paper A, eq. 18): viewpoint dependency strength
  double sharpness = 15.0;         // ViewpointGaussian: K in Σ_c = (RᵀR)⁻¹, R = K [[1, −0.5], [0, 1]]
  std::string table;               // a tabulated model file, where one stands in for the analytic one
};

struct SensorSpec {
  SensorKind kind = SensorKind::RangeBearing;
  Pose bodyToSensor = SE2();      // the sensor's pose in the robot frame
  double maxRange = 0.0;          // 0: unlimited
  double fieldOfView = 0.0;       // full angle in radians; 0: all around
};

struct PosePrior {
  Pose mean = SE2();
  Matrix covariance;  // tangent of the right perturbation, translation first
};

struct LandmarkPrior {
  int id = 0;
  LandmarkState mean = Point2(0.0, 0.0);
  Matrix covariance;
};

struct LandmarkTruth {
  int id = 0;
  int classIndex = -1;  // -1: unknown
  LandmarkState state = Point2(0.0, 0.0);
};

struct LogHeader {
  int version = 1;
  int dimension = 2;  // 2 or 3
  int classes = 1;    // M
  SemanticKind semantic = SemanticKind::None;
  ClassifierModelSpec classifier;
  SensorSpec sensor;
  bool landmarksHavePose = false;              // objects with an orientation (paper A) rather than points
  std::optional<PosePrior> initialPose;        // prior on the first pose
  std::vector<LandmarkPrior> landmarkPriors;   // a known but uncertain map, where there is one
  std::vector<LandmarkTruth> landmarkTruth;    // ground truth, where known
  std::string source;                          // free text: dataset, converter or simulator and its settings
};

struct Odometry {
  Pose increment = SE2();  // the motion from the previous step's pose, in its frame
  Matrix covariance;       // of the right perturbation of the increment
};

struct Detection {
  Vector geometry;                 // per SensorSpec::kind
  Matrix covariance;               // of the geometry (RelativePose: of its tangent)
  std::optional<int> label;        // SemanticKind::Label
  std::optional<Vector> classVector;  // SemanticKind::Probabilities or Scores (length classes)
  std::optional<int> truthId;      // a landmark id, kNotALandmark for clutter, kUnknownTruth where the dataset
                                   // cannot decide, or absent when the log has no truth for it
  std::optional<int> clutterSource;  // clutter only: which non-landmark object produced it, where the dataset
                                     // knows (e.g. MRCLAM's other robots), ≥ 0; ground truth, never method input
};

struct TimeStep {
  double time = 0.0;
  std::optional<Odometry> odometry;  // absent on the first step
  std::vector<Detection> detections;
  std::optional<Pose> truePose;
};

struct MeasurementLog {
  LogHeader header;
  std::vector<TimeStep> steps;
};

/// The truth a metric scores: a landmark id or kNotALandmark; std::nullopt for a detection without truth and for
/// kUnknownTruth, which every metric leaves out alike.
inline std::optional<int> scoredTruth(const std::optional<int>& truth) {
  if (!truth || *truth == kUnknownTruth) return std::nullopt;
  return truth;
}

}  // namespace semslam
