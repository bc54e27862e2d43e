#pragma once
// RangeBearingElevationFactor<Landmark>: a 3D range, bearing and elevation measurement of a landmark
// (RangeBearingElevationSensor3, with its body-to-sensor offset). The landmark is a point (Point3) or an object
// with a pose (SE3), of which the measurement sees the position.
//
// Error convention: e = z ⊖ h(x, l) = (z_r − h_r, wrap(z_b − h_b), wrap(z_e − h_e)); ∂e/∂· = −∂h/∂·.
// Variables: robot pose x (SE3), landmark l.

#include <cmath>
#include <numbers>
#include <optional>

#include "semslam/factors/LandmarkPosition.h"
#include "semslam/graph/NoiseModelFactor.h"
#include "semslam/models/PointInSensorFrame.h"
#include "semslam/models/RangeBearingElevationSensor3.h"

namespace semslam {

template <class Landmark>
class RangeBearingElevationFactor final : public NoiseModelFactor<3, SE3, Landmark> {
  using Base = NoiseModelFactor<3, SE3, Landmark>;

 public:
  using typename Base::ErrorVector;
  template <class V>
  using Jacobian = typename Base::template Jacobian<V>;

  RangeBearingElevationFactor(Key robot, Key landmark, const Vector3& measured, SharedNoiseModel noiseModel,
                              const RangeBearingElevationSensor3& sensor = RangeBearingElevationSensor3())
      : Base(std::move(noiseModel), {robot, landmark}), measured_(measured), sensor_(sensor) {}

  const Vector3& measured() const { return measured_; }
  const RangeBearingElevationSensor3& sensor() const { return sensor_; }

  ErrorVector evaluateError(const SE3& x, const Landmark& l, Jacobian<SE3>* Hx,
                            Jacobian<Landmark>* Hl) const override {
    MatrixN<3, Manifold<Landmark>::kDim> positionWrtLandmark;
    Matrix3 hWrtPosition;
    const Point3 position = LandmarkPosition<Landmark>::of(l, Hl ? &positionWrtLandmark : nullptr);
    const Vector3 predicted = sensor_.predict(x, position, Hx, Hl ? &hWrtPosition : nullptr);
    if (Hx) *Hx = -*Hx;
    if (Hl) *Hl = -hWrtPosition * positionWrtLandmark;
    return RangeBearingElevationSensor3::difference(measured_, predicted);
  }

  /// (Factor::whitenedErrorBoundForSeenMove) The landmark seen from the sensor, p, moves by at most ε (the sensor
  /// is fixed on the robot). At `from`, ρ₀ = ‖p₀‖ and h₀ = ‖(p₀ₓ, p₀ᵧ)‖. The range moves by at most ε; the bearing
  /// is the direction of (pₓ, pᵧ), which moves by at most ε too, so it turns by at most tan(asin(ε / h₀)) where
  /// ε < h₀; the elevation changes by at most the angle between p and p₀ (the polar angle is a distance on the
  /// sphere), at most tan(asin(ε / ρ₀)). Each angle's error stays off its ±π seam where |e_i(from)| plus its
  /// half-width is below π (NoiseModel::largestErrorEntry), and then ‖R Δe‖ is at most
  /// NoiseModel::largestWhitenedNormInBox. None under a robust kernel or where a condition fails.
  std::optional<double> whitenedErrorBoundForSeenMove(const Values& from, double chi2AtFrom,
                                                      double epsilon) const override {
    const NoiseModel& noise = *this->noiseModel();
    if (noise.robustKernel()) return std::nullopt;
    const Point3 position = LandmarkPosition<Landmark>::of(from.at<Landmark>(this->keys()[1]), nullptr);
    const Point3 seen =
        pointInSensorFrame(from.at<SE3>(this->keys()[0]), sensor_.bodyToSensor(), position, false, false).p;
    const double horizontal = seen.head<2>().norm();
    if (!(epsilon < horizontal)) return std::nullopt;  // the bearing could be anything (ρ₀ ≥ h₀)
    const auto turn = [](double sine) { return sine / std::sqrt(1.0 - sine * sine); };  // tan(asin(sine))
    const Vector3 halfWidths(epsilon, turn(epsilon / horizontal), turn(epsilon / seen.norm()));
    for (int i : {1, 2}) {
      if (!(noise.largestErrorEntry(i, chi2AtFrom) + halfWidths(i) < std::numbers::pi)) return std::nullopt;
    }
    return noise.largestWhitenedNormInBox(halfWidths);
  }

 private:
  Vector3 measured_;
  RangeBearingElevationSensor3 sensor_;
};

}  // namespace semslam
