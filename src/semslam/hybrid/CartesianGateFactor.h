#pragma once
// CartesianGateFactor<Landmark>: a range-bearing (2D) or range-bearing-elevation (3D) detection re-expressed as
// the landmark's position in the robot frame, for the gate and the linearised weights of PropWeights only (the
// components' beliefs keep the range-bearing(-elevation) factor). The robot pose is SE2 for a 2D landmark (Point2,
// SE2) and SE3 for a 3D one (Point3, SE3).
//
// Why. Under paper A's prior (σ = 10 m on the first pose) the linearisation point of a range-bearing factor can
// be tens of metres from the truth, where range and bearing are far from linear in the positions, and the
// linearised weight is useless as a gate. In Cartesian form the measurement is linear in both positions for a
// given orientation, z = Rᵀ (p_l − t) + v, so the linearised marginal likelihood stays accurate (it is exact in
// the positions; only the orientation remains nonlinear).
//
// Math. With the sensor mounted at s on the robot and the detection with covariance Σ:
//   2D  (r, b):     z_s = r (cos b, sin b),                        G = ∂z_s/∂(r, b)       (2×2);
//   3D  (r, b, e):  z_s = r (cos e cos b, cos e sin b, sin e),     G = ∂z_s/∂(r, b, e)    (3×3)
//                   (bearing about the sensor's z axis, elevation above its xy-plane: RangeBearingElevationSensor3);
//   Σ_s = G Σ Gᵀ;  z = s · z_s in the robot frame, Σ_z = R_s Σ_s R_sᵀ;
//   e = x⁻¹ · p(l) − z     (p(l) the landmark's position: LandmarkPosition.h)
//   ∂e/∂δx from transformTo, ∂e/∂δl = R_xᵀ ∂p/∂δl.
// A first-order transform of the noise: for r ≫ σ_r it is the same Gaussian to first order. On a planar 3D
// detection (e = 0, the robot and sensor level) the x, y block of the 3D factor is the 2D factor exactly.

#include <cmath>

#include "semslam/factors/LandmarkPosition.h"
#include "semslam/graph/NoiseModelFactor.h"

namespace semslam {

namespace cartesian_gate {
template <class Landmark>
inline constexpr int kDim = LandmarkPosition<Landmark>::Point::RowsAtCompileTime;
template <class Landmark>
using RobotPose = std::conditional_t<kDim<Landmark> == 2, SE2, SE3>;
}  // namespace cartesian_gate

template <class Landmark>
class CartesianGateFactor final
    : public NoiseModelFactor<cartesian_gate::kDim<Landmark>, cartesian_gate::RobotPose<Landmark>, Landmark> {
  static constexpr int kDim = cartesian_gate::kDim<Landmark>;
  using Robot = cartesian_gate::RobotPose<Landmark>;
  using Point = typename LandmarkPosition<Landmark>::Point;
  using Base = NoiseModelFactor<kDim, Robot, Landmark>;

 public:
  using typename Base::ErrorVector;
  template <class V>
  using Jacobian = typename Base::template Jacobian<V>;

  CartesianGateFactor(Key robot, Key landmark, const Point& measured, SharedNoiseModel noise)
      : Base(std::move(noise), {robot, landmark}), measured_(measured) {}

  /// From a range-bearing detection (r, b) with covariance Σ_rb, seen by a sensor mounted at `bodyToSensor`.
  static std::shared_ptr<const CartesianGateFactor> fromRangeBearing(Key robot, Key landmark, const Vector2& rb,
                                                                      const Matrix2& covariance,
                                                                      const SE2& bodyToSensor)
    requires(kDim == 2)
  {
    const double c = std::cos(rb(1)), s = std::sin(rb(1));
    Matrix2 G;
    G << c, -rb(0) * s, s, rb(0) * c;
    const Matrix2 Rs = bodyToSensor.rotation().matrix();
    const Matrix2 sigma = Rs * G * covariance * G.transpose() * Rs.transpose();
    const Point2 z = bodyToSensor.transformFrom(Point2(rb(0) * c, rb(0) * s));
    return std::make_shared<const CartesianGateFactor>(robot, landmark, z, NoiseModel::fromCovariance(sigma));
  }

  /// From a range-bearing-elevation detection (r, b, e) with covariance Σ_rbe, seen by a sensor at `bodyToSensor`.
  static std::shared_ptr<const CartesianGateFactor> fromRangeBearingElevation(Key robot, Key landmark,
                                                                               const Vector3& rbe,
                                                                               const Matrix3& covariance,
                                                                               const SE3& bodyToSensor)
    requires(kDim == 3)
  {
    const double r = rbe(0), cb = std::cos(rbe(1)), sb = std::sin(rbe(1)), ce = std::cos(rbe(2)),
                 se = std::sin(rbe(2));
    Matrix3 G;
    G << ce * cb, -r * ce * sb, -r * se * cb,  //
        ce * sb, r * ce * cb, -r * se * sb,    //
        se, 0.0, r * ce;
    const Matrix3 Rs = bodyToSensor.rotation().matrix();
    const Matrix3 sigma = Rs * G * covariance * G.transpose() * Rs.transpose();
    const Point3 z = bodyToSensor.transformFrom(Point3(r * ce * cb, r * ce * sb, r * se));
    return std::make_shared<const CartesianGateFactor>(robot, landmark, z, NoiseModel::fromCovariance(sigma));
  }

  ErrorVector evaluateError(const Robot& x, const Landmark& l, Jacobian<Robot>* Hx,
                            Jacobian<Landmark>* Hl) const override {
    MatrixN<kDim, Manifold<Landmark>::kDim> positionWrtLandmark;
    MatrixN<kDim, kDim> wrtPosition;
    const Point p = LandmarkPosition<Landmark>::of(l, Hl ? &positionWrtLandmark : nullptr);
    const Point local = x.transformTo(p, Hx, Hl ? &wrtPosition : nullptr);
    if (Hl) *Hl = wrtPosition * positionWrtLandmark;
    return local - measured_;
  }

 private:
  Point measured_;
};

}  // namespace semslam
