#pragma once
// MeasurementFactory: the one place that turns a measurement log's entries into factors and initial values, for
// every method (known association, max-mixtures, EM, the hybrid belief). It reads the log header once (dimension,
// sensor kind and mounting, whether landmarks are points or posed objects) and maps:
//
//   odometry between steps        → BetweenFactor<SE2|SE3>, noise = the odometry's covariance;
//   prior on the first pose       → PriorFactor<SE2|SE3>;
//   prior on a landmark (a map)   → PriorFactor<landmark type>;
//   detection of a landmark       → RangeBearingFactor (2D), RangeBearingElevationFactor (3D),
//                                   RelativePointFactor (RelativePosition), RelativePoseFactor (RelativePose),
//                                   noise = the detection's covariance times sigmaScale²;
//   a new landmark's initial value  the detection back-projected from the robot pose (the sensor's inverse);
//                                   a posed object seen by a position-only sensor starts with the robot's
//                                   orientation (its orientation is then fixed only by a prior or by other factors).
//
// Landmark variables are Point2/Point3 when the header says landmarks are points, SE2/SE3 when they have a pose.
// Every inconsistency (a detection of the wrong length, a 3D sensor in a 2D log, a pose of the wrong type) throws
// std::invalid_argument naming it.

#include "semslam/graph/Factor.h"
#include "semslam/graph/NoiseModel.h"
#include "semslam/graph/RobustKernel.h"
#include "semslam/graph/Values.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

class MeasurementFactory {
 public:
  explicit MeasurementFactory(const LogHeader& header);

  int dimension() const { return dimension_; }
  bool landmarksHavePose() const { return landmarksHavePose_; }
  /// Tangent dimension of a pose (3 or 6) and of a landmark variable (2, 3, 3 or 6).
  int poseTangentDimension() const { return dimension_ == 2 ? 3 : 6; }
  int landmarkTangentDimension() const;

  FactorPtr odometryFactor(Key from, Key to, const Odometry& odometry) const;
  FactorPtr posePriorFactor(Key pose, const PosePrior& prior) const;
  FactorPtr landmarkPriorFactor(Key landmark, const LandmarkPrior& prior) const;
  /// The detection's geometric factor between `pose` and `landmark`; sigmaScale multiplies its standard deviations
  /// (a null hypothesis is the same factor with a broad Gaussian); an optional robust kernel on its whitened error.
  FactorPtr detectionFactor(Key pose, Key landmark, const Detection& detection, double sigmaScale = 1.0,
                            SharedRobustKernel kernel = nullptr) const;
  /// The same with the noise model given: a detection weighed against several landmarks builds its noise model
  /// (detectionNoise) once.
  FactorPtr detectionFactor(Key pose, Key landmark, const Detection& detection, SharedNoiseModel noise) const;
  /// The noise model of detectionFactor: the detection's covariance times sigmaScale², with the optional kernel.
  SharedNoiseModel detectionNoise(const Detection& detection, double sigmaScale = 1.0,
                                  SharedRobustKernel kernel = nullptr) const;

  /// The pose after `odometry` from `previous`.
  Value predictPose(const Value& previous, const Odometry& odometry) const;
  /// The first pose: the prior's mean where the log has one, else the identity.
  Value initialPose(const LogHeader& header) const;
  /// A landmark value at the detection's back-projection from `robot`.
  Value initialLandmark(const Detection& detection, const Value& robot) const;
  /// A landmark value from a log's landmark state (prior mean or truth), converted to this problem's variable type.
  Value landmarkValue(const LandmarkState& state) const;
  /// The position part (2 or 3 numbers) of a landmark or pose value.
  static Vector positionOf(const Value& value);
  /// The detection's position error, in metres: √λmax of the covariance of its back-projected position,
  /// H_l⁻¹ R H_l⁻ᵀ with H_l = ∂h/∂l at that position and R the detection's covariance (the largest axis of its
  /// error ellipse; for a range-bearing detection with uncorrelated noise, max(σ_r, r σ_θ)). The same from any robot
  /// pose (a rotation leaves the eigenvalues alone). Relative position: √λmax(R); relative pose: of R's translation
  /// block. Throws std::domain_error for a detection at the sensor (range 0), where H_l is singular.
  double detectionPositionSigma(const Detection& detection) const;
  /// The position of `landmark` in the frame of the sensor mounted on `robot` (2 or 3 numbers).
  Vector positionInSensorFrame(const Value& robot, const Value& landmark) const;

 private:
  void checkDetection(const Detection& detection) const;

  int dimension_;
  bool landmarksHavePose_;
  SensorSpec sensor_;
};

}  // namespace semslam
