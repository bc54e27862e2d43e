#pragma once
// CartesianGateFactor<Landmark>: a range-bearing detection re-expressed as the landmark's position in the robot
// frame, for the gate of PropWeights only (the components' beliefs keep the range-bearing factor).
//
// Why. Under paper A's prior (σ = 10 m on the first pose) the linearisation point of a range-bearing factor can
// be tens of metres from the truth, where range and bearing are far from linear in the positions, and the
// linearised weight is useless as a gate. In Cartesian form the measurement is linear in both positions for a
// given heading, z = R(θ)ᵀ (p_l − t) + v, so the linearised marginal likelihood stays accurate (it is exact in
// the positions; only the heading, σ = 0.2 rad, remains nonlinear).
//
// Math. With the sensor mounted at s on the robot and the detection (r, b) with covariance Σ_rb:
//   z_s = r (cos b, sin b)             the point in the sensor frame, Σ_s = G Σ_rb Gᵀ, G = ∂z_s/∂(r, b);
//   z   = s · z_s                      in the robot frame, Σ_z = R_s Σ_s R_sᵀ;
//   e   = x⁻¹ · p(l) − z               (p(l) the landmark's position: LandmarkPosition.h)
//   ∂e/∂δx from SE2::transformTo, ∂e/∂δl = R_xᵀ ∂p/∂δl.
// A first-order transform of the noise: for r ≫ σ_r it is the same Gaussian to first order.

#include "semslam/factors/LandmarkPosition.h"
#include "semslam/graph/NoiseModelFactor.h"

namespace semslam {

template <class Landmark>
class CartesianGateFactor final : public NoiseModelFactor<2, SE2, Landmark> {
  using Base = NoiseModelFactor<2, SE2, Landmark>;

 public:
  using typename Base::ErrorVector;
  template <class V>
  using Jacobian = typename Base::template Jacobian<V>;

  CartesianGateFactor(Key robot, Key landmark, const Point2& measured, SharedNoiseModel noise)
      : Base(std::move(noise), {robot, landmark}), measured_(measured) {}

  /// From a range-bearing detection (r, b) with covariance Σ_rb, seen by a sensor mounted at `bodyToSensor`.
  static std::shared_ptr<const CartesianGateFactor> fromRangeBearing(Key robot, Key landmark, const Vector2& rb,
                                                                      const Matrix2& covariance,
                                                                      const SE2& bodyToSensor) {
    const double c = std::cos(rb(1)), s = std::sin(rb(1));
    Matrix2 G;
    G << c, -rb(0) * s, s, rb(0) * c;
    const Matrix2 Rs = bodyToSensor.rotation().matrix();
    const Matrix2 sigma = Rs * G * covariance * G.transpose() * Rs.transpose();
    const Point2 z = bodyToSensor.transformFrom(Point2(rb(0) * c, rb(0) * s));
    return std::make_shared<const CartesianGateFactor>(robot, landmark, z, NoiseModel::fromCovariance(sigma));
  }

  ErrorVector evaluateError(const SE2& x, const Landmark& l, Jacobian<SE2>* Hx,
                            Jacobian<Landmark>* Hl) const override {
    MatrixN<2, Manifold<Landmark>::kDim> positionWrtLandmark;
    Matrix2 wrtPosition;
    const Point2 p = LandmarkPosition<Landmark>::of(l, Hl ? &positionWrtLandmark : nullptr);
    const Point2 local = x.transformTo(p, Hx, Hl ? &wrtPosition : nullptr);
    if (Hl) *Hl = wrtPosition * positionWrtLandmark;
    return local - measured_;
  }

 private:
  Point2 measured_;
};

}  // namespace semslam
