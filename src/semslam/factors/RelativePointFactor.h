#pragma once
// RelativePointFactor<Pose, Point>: a landmark position measured in the robot's frame (g2o EDGE_SE2_XY,
// iSAM LANDMARK, a stereo or depth detection; 2D with SE2/Point2, 3D with SE3/Point3).
//
// Error convention: e = x⁻¹ · l − z = Rᵀ(l − t) − z, in the robot frame.
// Jacobians: from Pose::transformTo (right perturbation of x) and Rᵀ for the landmark.

#include <optional>

#include "semslam/graph/NoiseModelFactor.h"

namespace semslam {

template <class Pose, class Point>
class RelativePointFactor final : public NoiseModelFactor<Manifold<Point>::kDim, Pose, Point> {
  using Base = NoiseModelFactor<Manifold<Point>::kDim, Pose, Point>;

 public:
  using typename Base::ErrorVector;
  template <class V>
  using Jacobian = typename Base::template Jacobian<V>;

  RelativePointFactor(Key pose, Key landmark, const Point& measured, SharedNoiseModel noiseModel)
      : Base(std::move(noiseModel), {pose, landmark}), measured_(measured) {}

  const Point& measured() const { return measured_; }

  ErrorVector evaluateError(const Pose& x, const Point& l, Jacobian<Pose>* Hx, Jacobian<Point>* Hl) const override {
    return x.transformTo(l, Hx, Hl) - measured_;
  }

  /// (Factor::whitenedErrorBoundForSeenMove) e moves as p = x⁻¹ · l does, by at most ε, so ‖R Δe‖ ≤ ‖R‖₂ ε ≤
  /// ‖R‖_F ε. None under a robust kernel.
  std::optional<double> whitenedErrorBoundForSeenMove(const Values& /*from*/, double /*chi2AtFrom*/,
                                                      double epsilon) const override {
    const NoiseModel& noise = *this->noiseModel();
    if (noise.robustKernel()) return std::nullopt;
    return noise.sqrtInformation().norm() * epsilon;  // R is upper triangular (graph/NoiseModel.h)
  }

 private:
  Point measured_;
};

}  // namespace semslam
