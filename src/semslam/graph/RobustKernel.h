#pragma once
// Robust kernels ρ(s) on the squared whitened error s = ‖r‖², in the convention of Ceres' LossFunction:
// the factor's cost is ρ(s) instead of s, with ρ(0) = 0, ρ'(0) = 1 and ρ' > 0.
//
// The solvers use iteratively reweighted least squares: the whitened error and Jacobian are scaled by
// sqrt(ρ'(s)), which makes the gradient exact (∇ ½ρ(‖r‖²) = ρ'(s) Jᵀr) and drops only the curvature of ρ from
// the Gauss-Newton Hessian.

#include <memory>
#include <string>

namespace semslam {

class RobustKernel {
 public:
  virtual ~RobustKernel() = default;
  /// ρ(s) for the squared whitened error s ≥ 0.
  virtual double cost(double squaredError) const = 0;
  /// ρ'(s) > 0: the weight by which the kernel scales the squared error locally.
  virtual double weight(double squaredError) const = 0;
  virtual std::string name() const = 0;
};

/// Huber: ρ(s) = s for s ≤ k², 2k√s − k² beyond; quadratic near zero, linear in the error's norm far away.
class HuberKernel final : public RobustKernel {
 public:
  explicit HuberKernel(double threshold);
  double cost(double squaredError) const override;
  double weight(double squaredError) const override;
  std::string name() const override { return "huber"; }
  double threshold() const { return threshold_; }

 private:
  double threshold_;
};

/// Cauchy: ρ(s) = k² log(1 + s/k²); logarithmic growth, so gross outliers have a vanishing weight.
class CauchyKernel final : public RobustKernel {
 public:
  explicit CauchyKernel(double scale);
  double cost(double squaredError) const override;
  double weight(double squaredError) const override;
  std::string name() const override { return "cauchy"; }
  double scale() const { return scale_; }

 private:
  double scale_;
};

using SharedRobustKernel = std::shared_ptr<const RobustKernel>;

}  // namespace semslam
