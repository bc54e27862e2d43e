#include "semslam/sim/Aliased3dLift.h"

#include <map>
#include <stdexcept>
#include <string>

#include "semslam/models/RangeBearingElevationSensor3.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/VisibilityModel.h"
#include "semslam/sim/SimulationStreams.h"

namespace semslam {
namespace {

SE3 level(const SE2& x, double z = 0.0) {
  return SE3(SO3::fromAxisAngle(Vector3::UnitZ(), x.theta()), Point3(x.x(), x.y(), z));
}

Pose levelPose(const Pose& pose) { return level(std::get<SE2>(pose)); }

/// A 2D pose tangent covariance (x, y, θ) in the 3D tangent (ρ_x, ρ_y, ρ_z, φ_x, φ_y, φ_z): θ ↦ φ_z, with the
/// variances of z and of roll and pitch given.
Matrix embedPoseCovariance(const Matrix& planar, double zVariance, double tiltVariance) {
  const int from[3] = {0, 1, 2}, to[3] = {0, 1, 5};
  Matrix spatial = Matrix::Zero(6, 6);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) spatial(to[i], to[j]) = planar(from[i], from[j]);
  }
  spatial(2, 2) = zVariance;
  spatial(3, 3) = spatial(4, 4) = tiltVariance;
  return spatial;
}

/// A 2D covariance with one more, uncorrelated, last entry.
Matrix appendVariance(const Matrix& planar, double variance) {
  const Eigen::Index n = planar.rows();
  Matrix out = Matrix::Zero(n + 1, n + 1);
  out.topLeftCorner(n, n) = planar;
  out(n, n) = variance;
  return out;
}

LandmarkState liftState(const LandmarkState& state, double height) {
  if (const auto* p = std::get_if<Point2>(&state)) return Point3(p->x(), p->y(), height);
  if (const auto* o = std::get_if<SE2>(&state)) return level(*o, height);
  throw std::invalid_argument("aliased 3D lift: the log's landmarks are not 2D");
}

Matrix liftLandmarkCovariance(const LandmarkState& state, const Matrix& covariance, double zVariance,
                              double tiltVariance) {
  if (std::holds_alternative<Point2>(state)) return appendVariance(covariance, zVariance);
  return embedPoseCovariance(covariance, zVariance, tiltVariance);
}

Point3 positionOf(const LandmarkState& state) {
  if (const auto* p = std::get_if<Point3>(&state)) return *p;
  return std::get<SE3>(state).translation();
}

}  // namespace

MeasurementLog liftAliasedLogTo3d(const MeasurementLog& planar, const Aliased3dLift& lift, std::uint64_t seed,
                                  std::uint32_t track) {
  const LogHeader& h2 = planar.header;
  if (h2.dimension != 2) throw std::invalid_argument("aliased 3D lift: the log is not 2D");
  const bool withHeights = !lift.objectHeights.empty();
  if (h2.sensor.kind != SensorKind::RangeBearing &&
      (withHeights || h2.sensor.kind != SensorKind::RelativePosition)) {
    throw std::invalid_argument("aliased 3D lift: range-bearing logs (or relative-position ones, level) only");
  }
  if (withHeights && lift.objectHeights.size() != h2.landmarkTruth.size()) {
    throw std::invalid_argument("aliased 3D lift: " + std::to_string(lift.objectHeights.size()) + " heights for " +
                                std::to_string(h2.landmarkTruth.size()) + " objects");
  }
  if (!(lift.levelSigma > 0.0) || !(lift.elevationSigma > 0.0) || (withHeights && !(lift.heightSigma > 0.0))) {
    throw std::invalid_argument("aliased 3D lift: every sigma must be positive");
  }
  const double tilt = lift.levelSigma * lift.levelSigma;
  const double objectZ = withHeights ? lift.heightSigma * lift.heightSigma : tilt;
  std::map<int, double> heightOf;  // landmark id -> true height
  for (std::size_t j = 0; j < h2.landmarkTruth.size(); ++j) {
    heightOf[h2.landmarkTruth[j].id] = withHeights ? lift.objectHeights[j] : 0.0;
  }
  std::mt19937 rng = simulationStream(seed, track, SimStream::Lift3d);

  MeasurementLog out;
  LogHeader& h = out.header;
  h = h2;
  h.dimension = 3;
  h.sensor.bodyToSensor = levelPose(h2.sensor.bodyToSensor);
  if (h2.sensor.kind == SensorKind::RangeBearing) h.sensor.kind = SensorKind::RangeBearingElevation;
  if (h2.initialPose) {
    h.initialPose = PosePrior{levelPose(h2.initialPose->mean), embedPoseCovariance(h2.initialPose->covariance, tilt, tilt)};
  }
  for (LandmarkPrior& prior : h.landmarkPriors) {
    const double truth = heightOf.count(prior.id) ? heightOf[prior.id] : 0.0;
    const double mean = withHeights ? truth + lift.heightSigma * standardNormal(rng) : 0.0;
    prior.covariance = liftLandmarkCovariance(prior.mean, prior.covariance, objectZ, tilt);
    prior.mean = liftState(prior.mean, mean);
  }
  for (LandmarkTruth& truth : h.landmarkTruth) truth.state = liftState(truth.state, heightOf[truth.id]);
  h.source += withHeights ? "; lifted to 3D with object heights (sim/Aliased3dLift.h)" : "; lifted to 3D, level";

  std::map<int, Point3> truePosition;
  for (const LandmarkTruth& truth : h.landmarkTruth) truePosition[truth.id] = positionOf(truth.state);
  const RangeBearingElevationSensor3 sensor(std::get<SE3>(h.sensor.bodyToSensor));
  const VisibilityModel3 visibility = VisibilityModel3::fromSpec(h.sensor);
  const double elevationVariance = lift.elevationSigma * lift.elevationSigma;
  for (const TimeStep& step2 : planar.steps) {
    TimeStep step;
    step.time = step2.time;
    if (step2.odometry) {
      step.odometry = Odometry{levelPose(step2.odometry->increment),
                               embedPoseCovariance(step2.odometry->covariance, tilt, tilt)};
    }
    if (step2.truePose) step.truePose = levelPose(*step2.truePose);
    for (const Detection& d2 : step2.detections) {
      Detection d = d2;
      if (!withHeights) {
        d.geometry = Vector3(d2.geometry(0), d2.geometry(1), 0.0);
        d.covariance = appendVariance(d2.covariance, h2.sensor.kind == SensorKind::RangeBearing ? elevationVariance
                                                                                                  : tilt);
      } else {
        if (!step.truePose || !d2.truthId || !truePosition.count(*d2.truthId)) {
          throw std::invalid_argument("aliased 3D lift: a detection without a true pose or a true object");
        }
        const SE3& robot = std::get<SE3>(*step.truePose);
        const Point3& object = truePosition[*d2.truthId];
        d.covariance = appendVariance(d2.covariance, elevationVariance);
        const Vector noise = sampleGaussian(Vector::Zero(3), d.covariance, rng);  // drawn whether kept or not
        if (!visibility.visible(robot, object)) continue;
        d.geometry = sensor.predict(robot, object) + noise;
      }
      step.detections.push_back(std::move(d));
    }
    out.steps.push_back(std::move(step));
  }
  return out;
}

}  // namespace semslam
