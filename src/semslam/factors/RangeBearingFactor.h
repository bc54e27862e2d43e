#pragma once
// RangeBearingFactor<Landmark>: a planar range-bearing measurement z = (range, bearing) of a landmark from a
// sensor mounted on the robot (RangeBearingSensor2, with its body-to-sensor offset). The landmark is a point
// (Point2) or an object with a pose (SE2), of which the measurement sees the position.
//
// Error convention: e = z ⊖ h(x, l) = (z_range − h_range, wrap(z_bearing − h_bearing)), wrapped to (−π, π];
// hence ∂e/∂· = −∂h/∂·. Variables: robot pose x (SE2), landmark l.

#include "semslam/factors/LandmarkPosition.h"
#include "semslam/graph/NoiseModelFactor.h"
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

 private:
  Vector2 measured_;
  RangeBearingSensor2 sensor_;
};

}  // namespace semslam
