#include "semslam/sim/SemanticSimulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "semslam/models/CategoricalClassifierModel.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/VisibilityModel.h"
#include "semslam/sim/Clutter.h"
#include "semslam/sim/MeasurementSampling.h"
#include "semslam/sim/SimulationStreams.h"

namespace semslam {

namespace {

constexpr double kInitialPoseVariance = 1e-6;
constexpr double kZeroNoiseCovarianceScale = 1e-3;

void check(bool ok, const std::string& problem) {
  if (!ok) throw std::invalid_argument("semantic simulation: " + problem);
}

bool finite(double v) { return std::isfinite(v); }

/// The class index of a uniform draw: floor(u M), in [0, M).
int uniformClass(int classes, std::mt19937& rng) {
  return std::min(classes - 1, static_cast<int>(uniform01(rng) * classes));
}

template <class PoseT>
struct Traits;

template <>
struct Traits<SE2> {
  using Point = Point2;
  static constexpr int kDim = 2;
  static Point position(const SE2& pose) { return pose.translation(); }
  static Vector3 axisY(const SE2& pose) {
    const Point2 y = pose.rotation().rotate(Point2(0.0, 1.0));
    return Vector3(y.x(), y.y(), 0.0);
  }
  static Vector3 axisZ(const SE2&) { return Vector3::UnitZ(); }
  static Point fromVector3(const Vector3& v) { return v.head<2>(); }
  static Vector3 toVector3(const Point& p) { return Vector3(p.x(), p.y(), 0.0); }
  static SE2 retract(const SE2& pose, const Vector& delta) { return pose.retract(Vector3(delta)); }
};

template <>
struct Traits<SE3> {
  using Point = Point3;
  static constexpr int kDim = 3;
  static Point position(const SE3& pose) { return pose.translation(); }
  static Vector3 axisY(const SE3& pose) { return pose.rotation().matrix().col(1); }
  static Vector3 axisZ(const SE3& pose) { return pose.rotation().matrix().col(2); }
  static Point fromVector3(const Vector3& v) { return v; }
  static Vector3 toVector3(const Point& p) { return p; }
  static SE3 retract(const SE3& pose, const Vector& delta) { return pose.retract(Vector6(delta)); }
};

struct Landmark {
  int id = 0;
  int classIndex = 0;
  Vector3 position;  // z = 0 in 2D
};

template <class PoseT>
std::vector<Landmark> placeLandmarks(const std::vector<PoseT>& poses, const SemanticSimOptions& options,
                                     double pathLength, std::mt19937& rng) {
  using T = Traits<PoseT>;
  int count = options.landmarks;
  if (count == 0 && options.landmarkDensity > 0.0) {
    const double fromDensity = std::round(options.landmarkDensity * pathLength);
    check(fromDensity <= kMaxSimulatedLandmarks,
          "the landmark density times the path length gives more than " + std::to_string(kMaxSimulatedLandmarks) +
              " landmarks");
    count = std::max(1, static_cast<int>(fromDensity));
  }
  std::vector<double> cumulative(poses.size(), 0.0);
  for (std::size_t i = 1; i < poses.size(); ++i) {
    cumulative[i] = cumulative[i - 1] + (T::position(poses[i]) - T::position(poses[i - 1])).norm();
  }
  std::vector<Landmark> landmarks;
  for (int id = 0; id < count; ++id) {
    const double s = uniform01(rng) * pathLength;
    const double side = uniform01(rng) < 0.5 ? 1.0 : -1.0;
    const double offset = options.minOffset + uniform01(rng) * (options.maxOffset - options.minOffset);
    const double height = options.minHeight + uniform01(rng) * (options.maxHeight - options.minHeight);
    const int classIndex = uniformClass(options.classes, rng);
    // The segment [i, i + 1] holding s (the last one for s = L; the first pose when the path has no length).
    std::size_t i =
        static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), s) - cumulative.begin());
    i = i == 0 ? 0 : i - 1;
    i = std::min(i, poses.size() - 2);
    const double length = cumulative[i + 1] - cumulative[i];
    const double t = length > 0.0 ? std::clamp((s - cumulative[i]) / length, 0.0, 1.0) : 0.0;
    const Vector3 a = T::toVector3(T::position(poses[i]));
    const Vector3 b = T::toVector3(T::position(poses[i + 1]));
    Vector3 position = a + t * (b - a) + side * offset * T::axisY(poses[i]);
    if (T::kDim == 3) position += height * T::axisZ(poses[i]);
    landmarks.push_back({id, classIndex, position});
  }
  return landmarks;
}

std::string sourceText(const SemanticSimOptions& options, int dimension, std::uint64_t seed, std::size_t steps) {
  std::ostringstream text;
  text.precision(17);
  text << "semslam simulate semantic: " << dimension << "D, " << options.description << ", " << steps << " steps, seed "
       << seed << ", classes " << options.classes << ", misclassification " << options.misclassification
       << ", odom noise scale " << options.odomNoiseScale << ", clutter " << options.clutter
       << ", detection probability " << options.detectionProbability;
  return text.str();
}

template <class PoseT>
MeasurementLog simulate(const std::vector<PoseT>& poses, const std::vector<double>& times,
                        const SemanticSimOptions& options, std::uint64_t seed,
                        const std::function<void(int, int)>& progress) {
  using T = Traits<PoseT>;
  constexpr int d = T::kDim;
  std::mt19937 landmarkStream = simulationStream(seed, 0, SimStream::Landmarks);
  std::mt19937 motionNoise = simulationStream(seed, 0, SimStream::MotionNoise);
  std::mt19937 geometryNoise = simulationStream(seed, 0, SimStream::Geometry);
  std::mt19937 labels = simulationStream(seed, 0, SimStream::Semantic);
  std::mt19937 misses = simulationStream(seed, 0, SimStream::Detection);
  std::mt19937 clutterStream = simulationStream(seed, 0, SimStream::Clutter);

  double pathLength = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i)
    pathLength += (T::position(poses[i]) - T::position(poses[i - 1])).norm();
  const std::vector<Landmark> landmarks = placeLandmarks(poses, options, pathLength, landmarkStream);

  // One class: every label is 0 (the categorical model needs two classes to confuse).
  const std::optional<CategoricalClassifierModel> classifier =
      options.classes > 1
          ? std::optional<CategoricalClassifierModel>(std::in_place, options.classes, options.misclassification)
          : std::nullopt;
  const Matrix baseline = baselineOdometryCovariance(d);
  const double noiseScale = options.odomNoiseScale;
  const double covarianceScale =
      options.odomCovarianceScale.value_or(noiseScale > 0.0 ? noiseScale : kZeroNoiseCovarianceScale);
  const Matrix odometryCovariance = covarianceScale * covarianceScale * baseline;
  Matrix sensorCovariance = Matrix::Zero(d, d);
  sensorCovariance(0, 0) = options.rangeSigma * options.rangeSigma;
  sensorCovariance(1, 1) = options.bearingSigma * options.bearingSigma;
  if (d == 3) sensorCovariance(2, 2) = options.elevationSigma * options.elevationSigma;

  MeasurementLog log;
  LogHeader& header = log.header;
  header.dimension = d;
  header.classes = options.classes;
  header.semantic = SemanticKind::Label;
  header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  header.classifier.misclassification = options.misclassification;
  header.sensor.kind = d == 2 ? SensorKind::RangeBearing : SensorKind::RangeBearingElevation;
  header.sensor.bodyToSensor = PoseT();
  header.sensor.maxRange = options.maxRange;
  header.sensor.fieldOfView = options.fieldOfView;
  header.landmarksHavePose = false;
  PosePrior initial;
  initial.mean = poses.front();
  initial.covariance = kInitialPoseVariance * Matrix::Identity(PoseT::kDim, PoseT::kDim);
  header.initialPose = initial;
  for (const Landmark& landmark : landmarks) {
    header.landmarkTruth.push_back(LandmarkTruth{landmark.id, landmark.classIndex, T::fromVector3(landmark.position)});
  }
  header.source = sourceText(options, d, seed, poses.size() - 1);

  using Visibility = std::conditional_t<d == 2, VisibilityModel2, VisibilityModel3>;
  using Sensor = std::conditional_t<d == 2, RangeBearingSensor2, RangeBearingElevationSensor3>;
  const Visibility visibility(options.fieldOfView, options.maxRange, PoseT());
  const Sensor sensor{PoseT()};

  for (std::size_t k = 0; k < poses.size(); ++k) {
    const PoseT& pose = poses[k];
    TimeStep step;
    step.time = times[k];
    step.truePose = pose;
    if (k > 0) {
      const PoseT increment = poses[k - 1].between(pose);
      const Vector w = sampleGaussian(Vector::Zero(PoseT::kDim), baseline, motionNoise);
      step.odometry = Odometry{T::retract(increment, noiseScale * w), odometryCovariance};
    }
    for (const Landmark& landmark : landmarks) {
      const typename T::Point point = T::fromVector3(landmark.position);
      if (!visibility.visible(pose, point)) continue;
      const bool detected = uniform01(misses) < options.detectionProbability;
      std::optional<Vector> geometry;
      if constexpr (d == 2) {
        geometry = sampleRangeBearing(sensor, pose, point, sensorCovariance, geometryNoise);
      } else {
        geometry = sampleRangeBearingElevation(sensor, pose, point, sensorCovariance, geometryNoise);
      }
      const int label = classifier ? classifier->sampleLabel(landmark.classIndex, labels) : 0;
      if (!detected || !geometry) continue;
      Detection detection;
      detection.geometry = *geometry;
      detection.covariance = sensorCovariance;
      detection.label = label;
      detection.truthId = landmark.id;
      step.detections.push_back(std::move(detection));
    }
    const int falseDetections = samplePoisson(options.clutter, clutterStream);
    for (int i = 0; i < falseDetections; ++i) {
      Detection detection;
      if constexpr (d == 2) {
        detection.geometry = uniformRangeBearing(options.fieldOfView, options.maxRange, clutterStream);
      } else {
        detection.geometry = uniformRangeBearingElevation(options.fieldOfView, options.maxRange, clutterStream);
      }
      detection.covariance = sensorCovariance;
      detection.label = uniformClass(options.classes, clutterStream);
      detection.truthId = kNotALandmark;
      step.detections.push_back(std::move(detection));
    }
    sortDetectionsByBearing(step.detections);
    log.steps.push_back(std::move(step));
    if (progress) progress(static_cast<int>(k + 1), static_cast<int>(poses.size()));
  }
  return log;
}

}  // namespace

Matrix baselineOdometryCovariance(int dimension) {
  if (dimension == 2) return Vector3(0.02 * 0.02, 0.01 * 0.01, 0.005 * 0.005).asDiagonal();
  if (dimension == 3) {
    Vector6 v;
    v << 0.02 * 0.02, 0.01 * 0.01, 0.01 * 0.01, 0.002 * 0.002, 0.002 * 0.002, 0.005 * 0.005;
    return v.asDiagonal();
  }
  throw std::invalid_argument("the dimension must be 2 or 3, found " + std::to_string(dimension));
}

void validateSemanticSimOptions(const SemanticSimOptions& o) {
  check(o.classes >= 1, "classes must be >= 1");
  check(o.landmarks >= 0 && o.landmarks <= kMaxSimulatedLandmarks,
        "the number of landmarks must be in [0, " + std::to_string(kMaxSimulatedLandmarks) + "]");
  check(finite(o.landmarkDensity) && o.landmarkDensity >= 0.0, "the landmark density must be >= 0");
  check(finite(o.minOffset) && finite(o.maxOffset) && o.minOffset >= 0.0 && o.minOffset <= o.maxOffset,
        "the landmark offsets must satisfy 0 <= min <= max");
  check(finite(o.minHeight) && finite(o.maxHeight) && o.minHeight <= o.maxHeight,
        "the landmark heights must satisfy min <= max");
  check(finite(o.maxRange) && o.maxRange >= 0.0, "the maximum range must be >= 0 (0: unlimited)");
  check(finite(o.fieldOfView) && o.fieldOfView >= 0.0 && o.fieldOfView <= 2.0 * std::numbers::pi,
        "the field of view must be in [0, 2 pi] radians (0: all around)");
  check(finite(o.rangeSigma) && o.rangeSigma > 0.0, "the range sigma must be positive");
  check(finite(o.bearingSigma) && o.bearingSigma > 0.0, "the bearing sigma must be positive");
  check(finite(o.elevationSigma) && o.elevationSigma > 0.0, "the elevation sigma must be positive");
  check(finite(o.detectionProbability) && o.detectionProbability >= 0.0 && o.detectionProbability <= 1.0,
        "the detection probability must be in [0, 1]");
  check(finite(o.misclassification) && o.misclassification >= 0.0 && o.misclassification < 1.0,
        "the misclassification rate must be in [0, 1)");
  check(o.classes > 1 || o.misclassification == 0.0,
        "with 1 class there is no other class to confuse it with: the misclassification rate must be 0");
  check(finite(o.odomNoiseScale) && o.odomNoiseScale >= 0.0, "the odometry noise scale must be >= 0");
  check(!o.odomCovarianceScale || (finite(*o.odomCovarianceScale) && *o.odomCovarianceScale > 0.0),
        "the odometry covariance scale must be positive");
  check(finite(o.clutter) && o.clutter >= 0.0 && o.clutter <= kMaxClutterMean,
        "the clutter rate must be in [0, 100] false detections per step");
  check(o.clutter == 0.0 || o.maxRange > 0.0, "clutter needs a positive maximum range (uniform in a bounded region)");
}

MeasurementLog simulateSemantic(const SimTrajectory& truth, const SemanticSimOptions& options, std::uint64_t seed,
                                const std::function<void(int, int)>& progress) {
  validateSemanticSimOptions(options);
  check(truth.poses.size() >= 2, "the trajectory needs at least two poses");
  check(truth.times.size() == truth.poses.size(), "one time per pose is needed");
  for (std::size_t i = 1; i < truth.times.size(); ++i)
    check(truth.times[i] > truth.times[i - 1], "times must increase");
  if (truth.dimension() == 2) {
    std::vector<SE2> poses;
    for (const Pose& pose : truth.poses) {
      check(std::holds_alternative<SE2>(pose), "the trajectory mixes SE2 and SE3 poses");
      poses.push_back(std::get<SE2>(pose));
    }
    return simulate(poses, truth.times, options, seed, progress);
  }
  std::vector<SE3> poses;
  for (const Pose& pose : truth.poses) {
    check(std::holds_alternative<SE3>(pose), "the trajectory mixes SE2 and SE3 poses");
    poses.push_back(std::get<SE3>(pose));
  }
  return simulate(poses, truth.times, options, seed, progress);
}

}  // namespace semslam
