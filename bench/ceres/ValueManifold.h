#pragma once
// ValueManifold: a ceres::Manifold for one kind of semslam value, in the ambient coordinates of
// AmbientCoordinates.h (as many numbers as the tangent has).
//
//   Plus(x, δ)   = our retract: x ⊕ δ = x · Exp(δ) (x + δ for points), decoded from and encoded back to x's
//                  ambient coordinates;
//   Minus(y, x)  = our local coordinates y ⊖ x = Log(x⁻¹ · y), so Minus(Plus(x, δ), x) = δ;
//   PlusJacobian = MinusJacobian = identity.
//
// Why the identity is right. Ceres never uses a cost function's Jacobian J_a (with respect to the ambient
// coordinates) on its own: its trust-region steps are computed in the tangent space with J_t = J_a · P, where
// P = ∂Plus(x, δ)/∂δ at δ = 0 (ambient × tangent). FactorCostFunction reports our own Jacobian with respect to
// the right perturbation, ∂r/∂δ, in the place of J_a. Paired with P = I the product Ceres forms is exactly
// ∂r/∂δ, the tangent Jacobian our own solver uses: the same step, the same Gauss-Newton Hessian, so both
// solvers run the same mathematics and any time difference is solver machinery. (The true J_a of our chart
// would be ∂r/∂δ · P_true⁻¹; reporting it together with P_true would give the same product at extra cost.) This
// pairing needs ambient size = tangent size, hence AmbientCoordinates' charts.

#include <ceres/manifold.h>

#include "AmbientCoordinates.h"

namespace semslam::bench {

class ValueManifold final : public ceres::Manifold {
 public:
  explicit ValueManifold(ValueKind kind);

  int AmbientSize() const override { return size_; }
  int TangentSize() const override { return size_; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool RightMultiplyByPlusJacobian(const double* x, int num_rows, const double* ambient_matrix,
                                   double* tangent_matrix) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;

 private:
  ValueKind kind_;
  int size_;
};

}  // namespace semslam::bench
