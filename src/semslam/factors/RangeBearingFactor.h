#pragma once
// RangeBearingFactor<Landmark>: a planar range-bearing measurement z = (range, bearing) of a landmark from a
// sensor mounted on the robot (RangeBearingSensor2, with its body-to-sensor offset). The landmark is a point
// (Point2) or an object with a pose (SE2), of which the measurement sees the position.
//
// Error convention: e = z ⊖ h(x, l) = (z_range − h_range, wrap(z_bearing − h_bearing)), wrapped to (−π, π];
// hence ∂e/∂· = −∂h/∂·. Variables: robot pose x (SE2), landmark l.

#include <cmath>
#include <numbers>
#include <optional>

#include "semslam/factors/LandmarkPosition.h"
#include "semslam/graph/NoiseModelFactor.h"
#include "semslam/models/PointInSensorFrame.h"
#include "semslam/models/RangeBearingSensor2.h"

namespace semslam {

template <class Landmark>
class RangeBearingFactor final : public NoiseModelFactor<2, SE2, Landmark> {
  using Base = NoiseModelFactor<2, SE2, Landmark>;

 public:
  using typename Base::ErrorVector;
  template <class V>
  using Jacobian = typename Base::template Jacobian<V>;

  RangeBearingFactor(Key robot, Key landmark, const Vector2& measured, SharedNoiseModel noiseModel,
                     const RangeBearingSensor2& sensor = RangeBearingSensor2())
      : Base(std::move(noiseModel), {robot, landmark}), measured_(measured), sensor_(sensor) {}

  const Vector2& measured() const { return measured_; }
  const RangeBearingSensor2& sensor() const { return sensor_; }

  ErrorVector evaluateError(const SE2& x, const Landmark& l, Jacobian<SE2>* Hx,
                            Jacobian<Landmark>* Hl) const override {
    MatrixN<2, Manifold<Landmark>::kDim> positionWrtLandmark;
    Matrix2 hWrtPosition;
    const Point2 position = LandmarkPosition<Landmark>::of(l, Hl ? &positionWrtLandmark : nullptr);
    const Vector2 predicted = sensor_.predict(x, position, Hx, Hl ? &hWrtPosition : nullptr);
    if (Hx) *Hx = -*Hx;
    if (Hl) *Hl = -hWrtPosition * positionWrtLandmark;
    return RangeBearingSensor2::difference(measured_, predicted);
  }

  /// (Factor::whitenedErrorBoundForSeenMove) The sensor is fixed on the robot, so the landmark seen from the sensor
  /// moves by what p = x⁻¹ · l moves, at most ε. From ρ₀, its distance from the sensor at `from`, the range moves by
  /// at most a = ε and, where ε < ρ₀, the bearing by at most asin(ε / ρ₀) ≤ b = tan(asin(ε / ρ₀)) (the widest angle
  /// a ball of radius ε subtends at distance ρ₀). The bearing error stays off its ±π seam where |e_b(from)| + b < π,
  /// and |e_b(from)| ≤ ‖r(from)‖ √Σ_bb (NoiseModel::largestErrorEntry); then Δe lies in the box |Δe_r| ≤ a,
  /// |Δe_b| ≤ b, and ‖R Δe‖ is at most NoiseModel::largestWhitenedNormInBox. None under a robust kernel or where
  /// either condition fails.
  std::optional<double> whitenedErrorBoundForSeenMove(const Values& from, double chi2AtFrom,
                                                      double epsilon) const override {
    const NoiseModel& noise = *this->noiseModel();
    if (noise.robustKernel()) return std::nullopt;
    const Point2 position = LandmarkPosition<Landmark>::of(from.at<Landmark>(this->keys()[1]), nullptr);
    const double distance =
        pointInSensorFrame(from.at<SE2>(this->keys()[0]), sensor_.bodyToSensor(), position, false, false).p.norm();
    if (!(epsilon < distance)) return std::nullopt;
    const double sine = epsilon / distance;
    const Vector2 halfWidths(epsilon, sine / std::sqrt(1.0 - sine * sine));  // a, b
    if (!(noise.largestErrorEntry(1, chi2AtFrom) + halfWidths(1) < std::numbers::pi)) return std::nullopt;
    return noise.largestWhitenedNormInBox(halfWidths);
  }

 private:
  Vector2 measured_;
  RangeBearingSensor2 sensor_;
};

}  // namespace semslam
