#pragma once
// RangeBearingElevationFactor<Landmark>: a 3D range, bearing and elevation measurement of a landmark
// (RangeBearingElevationSensor3, with its body-to-sensor offset). The landmark is a point (Point3) or an object
// with a pose (SE3), of which the measurement sees the position.
//
// Error convention: e = z ⊖ h(x, l) = (z_r − h_r, wrap(z_b − h_b), wrap(z_e − h_e)); ∂e/∂· = −∂h/∂·.
// Variables: robot pose x (SE3), landmark l.

#include "semslam/factors/LandmarkPosition.h"
#include "semslam/graph/NoiseModelFactor.h"
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

 private:
  Vector3 measured_;
  RangeBearingElevationSensor3 sensor_;
};

}  // namespace semslam
