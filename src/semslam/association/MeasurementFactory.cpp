#include "semslam/association/MeasurementFactory.h"

#include <Eigen/LU>

#include <stdexcept>
#include <string>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RangeBearingElevationFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/geometry/CovarianceSpread.h"
#include "semslam/graph/NoiseModel.h"

namespace semslam {
namespace {

int expectedGeometryLength(SensorKind kind, int dimension) {
  switch (kind) {
    case SensorKind::RangeBearing: return 2;
    case SensorKind::RangeBearingElevation: return 3;
    case SensorKind::RelativePosition: return dimension;
    case SensorKind::RelativePose: return dimension == 2 ? 3 : 7;
  }
  return 0;
}

int expectedCovarianceSize(SensorKind kind, int dimension) {
  return kind == SensorKind::RelativePose ? (dimension == 2 ? 3 : 6) : expectedGeometryLength(kind, dimension);
}

bool isIdentity(const Pose& pose) {
  if (const auto* se2 = std::get_if<SE2>(&pose)) return se2->translation().isZero(0.0) && se2->theta() == 0.0;
  const SE3& se3 = std::get<SE3>(pose);
  return se3.translation().isZero(0.0) && se3.rotation().matrix().isIdentity(0.0);
}

SE3 relativePose3(const Vector& g) {
  const Eigen::Quaterniond q(g(6), g(3), g(4), g(5));
  return SE3(SO3::fromQuaternion(q), Point3(g(0), g(1), g(2)));
}

template <class T>
FactorPtr prior(Key key, const T& mean, const Matrix& covariance) {
  return std::make_shared<const PriorFactor<T>>(key, mean, NoiseModel::fromCovariance(covariance));
}

}  // namespace

MeasurementFactory::MeasurementFactory(const LogHeader& header)
    : dimension_(header.dimension), landmarksHavePose_(header.landmarksHavePose), sensor_(header.sensor) {
  if (dimension_ != 2 && dimension_ != 3) {
    throw std::invalid_argument("log dimension must be 2 or 3, not " + std::to_string(dimension_));
  }
  const bool sensorIs2d = std::holds_alternative<SE2>(sensor_.bodyToSensor);
  if (sensorIs2d != (dimension_ == 2)) throw std::invalid_argument("sensor mounting pose does not fit the log dimension");
  if (sensor_.kind == SensorKind::RangeBearing && dimension_ != 2) {
    throw std::invalid_argument("a range-bearing sensor needs a 2D log (3D: range-bearing-elevation)");
  }
  if (sensor_.kind == SensorKind::RangeBearingElevation && dimension_ != 3) {
    throw std::invalid_argument("a range-bearing-elevation sensor needs a 3D log");
  }
  if ((sensor_.kind == SensorKind::RelativePosition || sensor_.kind == SensorKind::RelativePose) &&
      !isIdentity(sensor_.bodyToSensor)) {
    throw std::invalid_argument("relative position and pose sensors must be mounted at the body frame");
  }
  if (sensor_.kind == SensorKind::RelativePose && !landmarksHavePose_) {
    throw std::invalid_argument("a relative-pose sensor needs landmarks with a pose");
  }
}

int MeasurementFactory::landmarkTangentDimension() const {
  if (landmarksHavePose_) return dimension_ == 2 ? 3 : 6;
  return dimension_;
}

void MeasurementFactory::checkDetection(const Detection& detection) const {
  const int length = expectedGeometryLength(sensor_.kind, dimension_);
  const int covarianceSize = expectedCovarianceSize(sensor_.kind, dimension_);
  if (detection.geometry.size() != length) {
    throw std::invalid_argument("detection has " + std::to_string(detection.geometry.size()) +
                                " geometry numbers, the sensor gives " + std::to_string(length));
  }
  if (detection.covariance.rows() != covarianceSize || detection.covariance.cols() != covarianceSize) {
    throw std::invalid_argument("detection covariance is not " + std::to_string(covarianceSize) + "x" +
                                std::to_string(covarianceSize));
  }
}

FactorPtr MeasurementFactory::odometryFactor(Key from, Key to, const Odometry& odometry) const {
  const SharedNoiseModel noise = NoiseModel::fromCovariance(odometry.covariance);
  if (dimension_ == 2) return std::make_shared<const BetweenFactor<SE2>>(from, to, std::get<SE2>(odometry.increment), noise);
  return std::make_shared<const BetweenFactor<SE3>>(from, to, std::get<SE3>(odometry.increment), noise);
}

FactorPtr MeasurementFactory::posePriorFactor(Key pose, const PosePrior& prior) const {
  if (dimension_ == 2) return semslam::prior(pose, std::get<SE2>(prior.mean), prior.covariance);
  return semslam::prior(pose, std::get<SE3>(prior.mean), prior.covariance);
}

FactorPtr MeasurementFactory::landmarkPriorFactor(Key landmark, const LandmarkPrior& landmarkPrior) const {
  return std::visit([&](const auto& mean) { return prior(landmark, mean, landmarkPrior.covariance); },
                    landmarkValue(landmarkPrior.mean));
}

SharedNoiseModel MeasurementFactory::detectionNoise(const Detection& detection, double sigmaScale,
                                                   SharedRobustKernel kernel) const {
  checkDetection(detection);
  if (!(sigmaScale > 0.0)) throw std::invalid_argument("sigma scale must be positive");
  SharedNoiseModel noise = NoiseModel::fromCovariance(detection.covariance * (sigmaScale * sigmaScale));
  if (kernel) noise = noise->withRobustKernel(std::move(kernel));
  return noise;
}

FactorPtr MeasurementFactory::detectionFactor(Key pose, Key landmark, const Detection& detection,
                                              double sigmaScale, SharedRobustKernel kernel) const {
  return detectionFactor(pose, landmark, detection, detectionNoise(detection, sigmaScale, std::move(kernel)));
}

FactorPtr MeasurementFactory::detectionFactor(Key pose, Key landmark, const Detection& detection,
                                              SharedNoiseModel noise) const {
  checkDetection(detection);
  if (!noise || noise->dimension() != detection.covariance.rows()) {
    throw std::invalid_argument("detection noise model does not match the detection's covariance");
  }
  const Vector& g = detection.geometry;
  switch (sensor_.kind) {
    case SensorKind::RangeBearing: {
      const RangeBearingSensor2 sensor(std::get<SE2>(sensor_.bodyToSensor));
      if (landmarksHavePose_) return std::make_shared<const RangeBearingFactor<SE2>>(pose, landmark, g, noise, sensor);
      return std::make_shared<const RangeBearingFactor<Point2>>(pose, landmark, g, noise, sensor);
    }
    case SensorKind::RangeBearingElevation: {
      const RangeBearingElevationSensor3 sensor(std::get<SE3>(sensor_.bodyToSensor));
      if (landmarksHavePose_) {
        return std::make_shared<const RangeBearingElevationFactor<SE3>>(pose, landmark, g, noise, sensor);
      }
      return std::make_shared<const RangeBearingElevationFactor<Point3>>(pose, landmark, g, noise, sensor);
    }
    case SensorKind::RelativePosition:
      if (landmarksHavePose_) throw std::invalid_argument("relative-position detections of posed landmarks are not supported");
      if (dimension_ == 2) return std::make_shared<const RelativePointFactor<SE2, Point2>>(pose, landmark, g, noise);
      return std::make_shared<const RelativePointFactor<SE3, Point3>>(pose, landmark, g, noise);
    case SensorKind::RelativePose:
      if (dimension_ == 2) return std::make_shared<const BetweenFactor<SE2>>(pose, landmark, SE2(g(0), g(1), g(2)), noise);
      return std::make_shared<const BetweenFactor<SE3>>(pose, landmark, relativePose3(g), noise);
  }
  throw std::invalid_argument("unknown sensor kind");
}

Value MeasurementFactory::predictPose(const Value& previous, const Odometry& odometry) const {
  if (dimension_ == 2) return std::get<SE2>(previous).compose(std::get<SE2>(odometry.increment));
  return std::get<SE3>(previous).compose(std::get<SE3>(odometry.increment));
}

Value MeasurementFactory::initialPose(const LogHeader& header) const {
  if (header.initialPose) {
    if (dimension_ == 2) return std::get<SE2>(header.initialPose->mean);
    return std::get<SE3>(header.initialPose->mean);
  }
  if (dimension_ == 2) return SE2();
  return SE3();
}

Value MeasurementFactory::initialLandmark(const Detection& detection, const Value& robot) const {
  checkDetection(detection);
  const Vector& g = detection.geometry;
  if (dimension_ == 2) {
    const SE2& x = std::get<SE2>(robot);
    Point2 position;
    switch (sensor_.kind) {
      case SensorKind::RangeBearing:
        position = RangeBearingSensor2(std::get<SE2>(sensor_.bodyToSensor)).backProject(x, g);
        break;
      case SensorKind::RelativePosition: position = x.transformFrom(Point2(g(0), g(1))); break;
      case SensorKind::RelativePose: return x.compose(SE2(g(0), g(1), g(2)));
      default: throw std::invalid_argument("sensor kind does not fit a 2D log");
    }
    if (landmarksHavePose_) return SE2(x.rotation(), position);
    return position;
  }
  const SE3& x = std::get<SE3>(robot);
  Point3 position;
  switch (sensor_.kind) {
    case SensorKind::RangeBearingElevation:
      position = RangeBearingElevationSensor3(std::get<SE3>(sensor_.bodyToSensor)).backProject(x, g);
      break;
    case SensorKind::RelativePosition: position = x.transformFrom(Point3(g(0), g(1), g(2))); break;
    case SensorKind::RelativePose: return x.compose(relativePose3(g));
    default: throw std::invalid_argument("sensor kind does not fit a 3D log");
  }
  if (landmarksHavePose_) return SE3(x.rotation(), position);
  return position;
}

namespace {

/// H_l⁻¹ R H_l⁻ᵀ: the covariance of the point that a sensor model h with ∂h/∂l = H_l back-projects.
Matrix backProjectedCovariance(const Matrix& pointJacobian, const Matrix& measurementCovariance) {
  const Eigen::FullPivLU<Matrix> lu(pointJacobian);
  if (!lu.isInvertible()) throw std::domain_error("detection at the sensor: its position error is undefined");
  const Matrix inverse = lu.inverse();
  return inverse * measurementCovariance * inverse.transpose();
}

/// The largest standard deviation of the point a range-bearing(-elevation) `sensor` back-projects from `geometry`
/// with covariance R, seen from the origin: √λmax(H_l⁻¹ R H_l⁻ᵀ).
template <typename Pose, int dimension, typename Sensor>
double backProjectedSigma(const Sensor& sensor, const Vector& geometry, const Matrix& R) {
  const auto point = sensor.backProject(Pose(), geometry);
  Eigen::Matrix<double, dimension, dimension> pointJacobian;
  sensor.predict(Pose(), point, nullptr, &pointJacobian);
  return largestStandardDeviation(backProjectedCovariance(pointJacobian, R));
}

}  // namespace

double MeasurementFactory::detectionPositionSigma(const Detection& detection) const {
  checkDetection(detection);
  const Matrix& R = detection.covariance;
  switch (sensor_.kind) {
    case SensorKind::RangeBearing:
      return backProjectedSigma<SE2, 2>(RangeBearingSensor2(std::get<SE2>(sensor_.bodyToSensor)), detection.geometry, R);
    case SensorKind::RangeBearingElevation:
      return backProjectedSigma<SE3, 3>(RangeBearingElevationSensor3(std::get<SE3>(sensor_.bodyToSensor)),
                                        detection.geometry, R);
    case SensorKind::RelativePosition: return largestStandardDeviation(R);
    case SensorKind::RelativePose: return largestStandardDeviation(R.topLeftCorner(dimension_, dimension_));
  }
  throw std::invalid_argument("unknown sensor kind");
}

Value MeasurementFactory::landmarkValue(const LandmarkState& state) const {
  return std::visit(
      [&](const auto& s) -> Value {
        using S = std::decay_t<decltype(s)>;
        constexpr int stateDimension = (std::is_same_v<S, Point2> || std::is_same_v<S, SE2>) ? 2 : 3;
        if (stateDimension != dimension_) throw std::invalid_argument("landmark state does not fit the log dimension");
        constexpr bool statehasPose = std::is_same_v<S, SE2> || std::is_same_v<S, SE3>;
        if constexpr (statehasPose) {
          if (landmarksHavePose_) return s;
          return s.translation();
        } else {
          if (!landmarksHavePose_) return s;
          if constexpr (std::is_same_v<S, Point2>) return SE2(SO2(), s);
          else return SE3(SO3(), s);
        }
      },
      state);
}

Vector MeasurementFactory::positionOf(const Value& value) {
  return std::visit(
      [](const auto& v) -> Vector {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, Point2> || std::is_same_v<V, Point3>) return v;
        else if constexpr (std::is_same_v<V, SE2> || std::is_same_v<V, SE3>) return v.translation();
        else throw std::invalid_argument("a rotation has no position");
      },
      value);
}

Vector MeasurementFactory::positionInSensorFrame(const Value& robot, const Value& landmark) const {
  const Vector position = positionOf(landmark);
  if (dimension_ == 2) {
    const SE2 sensor = std::get<SE2>(robot).compose(std::get<SE2>(sensor_.bodyToSensor));
    return sensor.transformTo(Point2(position(0), position(1)));
  }
  const SE3 sensor = std::get<SE3>(robot).compose(std::get<SE3>(sensor_.bodyToSensor));
  return sensor.transformTo(Point3(position(0), position(1), position(2)));
}

}  // namespace semslam
