// MeasurementFactory::detectionPositionSigma: the largest standard deviation of a detection's back-projected
// position, against closed forms. A polar detection's back-projection p(r, θ[, φ]) has the Jacobian
// Rot · diag(1, r cos φ, r) in the (range, bearing, elevation) directions, which are orthonormal, so the position
// covariance has the eigenvalues of D R D with D = diag(1, r cos φ, r) (2D: diag(1, r)), whatever the robot pose or
// the sensor mounting.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

#include "semslam/association/MeasurementFactory.h"

using namespace semslam;

namespace {

LogHeader headerFor(int dimension, SensorKind kind) {
  LogHeader header;
  header.dimension = dimension;
  header.sensor.kind = kind;
  // Polar sensors mounted off the body origin (the result must not depend on it); relative ones sit at the origin.
  const bool polar = kind == SensorKind::RangeBearing || kind == SensorKind::RangeBearingElevation;
  if (dimension == 2) {
    header.sensor.bodyToSensor = polar ? SE2(0.3, -0.1, 0.4) : SE2();
  } else {
    header.sensor.bodyToSensor = polar ? SE3(SO3::Exp(Vector3(0.1, -0.2, 0.3)), Point3(0.2, 0.0, 1.1)) : SE3();
  }
  return header;
}

Detection detectionOf(Vector geometry, Matrix covariance) {
  Detection detection;
  detection.geometry = std::move(geometry);
  detection.covariance = std::move(covariance);
  return detection;
}

double largestSigma(const Matrix& covariance) {
  return std::sqrt(Eigen::SelfAdjointEigenSolver<Matrix>(covariance).eigenvalues().maxCoeff());
}

}  // namespace

TEST(DetectionPositionSigma, RangeBearingWithUncorrelatedNoiseIsTheLargerOfRangeAndLateralSigma) {
  const MeasurementFactory factory(headerFor(2, SensorKind::RangeBearing));
  const Matrix R = Vector2(0.21 * 0.21, 0.014 * 0.014).asDiagonal();
  // Near: the range σ dominates (r σ_θ = 0.028 m at 2 m); far: the lateral one (0.14 m at 10 m).
  EXPECT_NEAR(factory.detectionPositionSigma(detectionOf(Vector2(2.0, 0.3), R)), 0.21, 1e-12);
  EXPECT_NEAR(factory.detectionPositionSigma(detectionOf(Vector2(20.0, -2.9), R)), 20.0 * 0.014, 1e-12);
}

TEST(DetectionPositionSigma, RangeBearingWithCorrelatedNoiseMatchesTheClosedForm) {
  const MeasurementFactory factory(headerFor(2, SensorKind::RangeBearing));
  Matrix R(2, 2);
  R << 0.04, 0.003, 0.003, 0.0009;
  for (double range : {0.5, 3.0, 12.0}) {
    const Matrix D = Vector2(1.0, range).asDiagonal();
    EXPECT_NEAR(factory.detectionPositionSigma(detectionOf(Vector2(range, 1.1), R)), largestSigma(D * R * D), 1e-12)
        << "range " << range;
  }
}

TEST(DetectionPositionSigma, RangeBearingElevationMatchesTheClosedForm) {
  const MeasurementFactory factory(headerFor(3, SensorKind::RangeBearingElevation));
  Matrix R(3, 3);
  R << 0.01, 0.001, -0.0005, 0.001, 0.0004, 0.0001, -0.0005, 0.0001, 0.0009;
  for (double elevation : {0.0, 0.4, -1.2}) {
    const double range = 7.0;
    const Matrix D = Vector3(1.0, range * std::cos(elevation), range).asDiagonal();
    EXPECT_NEAR(factory.detectionPositionSigma(detectionOf(Vector3(range, -0.7, elevation), R)),
                largestSigma(D * R * D), 1e-12)
        << "elevation " << elevation;
  }
}

TEST(DetectionPositionSigma, RelativePositionAndPoseUseTheirTranslationCovariance) {
  Matrix R(2, 2);
  R << 0.09, 0.02, 0.02, 0.01;
  EXPECT_NEAR(MeasurementFactory(headerFor(2, SensorKind::RelativePosition))
                  .detectionPositionSigma(detectionOf(Vector2(4.0, 1.0), R)),
              largestSigma(R), 1e-12);
  LogHeader posed = headerFor(2, SensorKind::RelativePose);
  posed.landmarksHavePose = true;
  Matrix poseCovariance = Matrix::Zero(3, 3);
  poseCovariance.topLeftCorner(2, 2) = R;
  poseCovariance(2, 2) = 4.0;  // a large orientation variance is not a position error
  EXPECT_NEAR(MeasurementFactory(posed).detectionPositionSigma(detectionOf(Vector3(4.0, 1.0, 0.2), poseCovariance)),
              largestSigma(R), 1e-12);
}

TEST(DetectionPositionSigma, ADetectionAtTheSensorHasNoPositionError) {
  const MeasurementFactory factory(headerFor(2, SensorKind::RangeBearing));
  EXPECT_THROW(factory.detectionPositionSigma(detectionOf(Vector2(0.0, 0.0), Matrix::Identity(2, 2))),
               std::domain_error);
}
