#pragma once
// ViewpointSemanticFactor<Pose>: the viewpoint-dependent semantic measurement factor of paper A,
//     P(z_sem | c, x, x_o) = N(z_sem; h_c(θ), Σ_c(θ)),   θ = θ(x · s, x_o)                  (A, eq. 2, 10, 18)
// for a classifier output z_sem (length d) of an object of hypothesised class c, seen by the sensor mounted at s
// on the robot pose x, the object having the pose x_o. Pose is SE2 or SE3 (robot and object alike); θ is
// models/Viewpoint.h's angle (the bearing of the camera seen from the object's frame).
//
// Error convention: e = z_sem − h_c(θ), whitened with the square-root information R(θ) of Σ_c(θ):
//     r = R(θ) (z_sem − h_c(θ)),
//     ∂r/∂δx   = −R(θ) dh_c/dθ · ∂θ/∂δcam · Ad(s⁻¹)     (∂(x·s)/∂δx = Ad(s⁻¹): SE2/SE3::compose's first Jacobian)
//     ∂r/∂δx_o = −R(θ) dh_c/dθ · ∂θ/∂δx_o.
// Σ_c's own dependence on θ is held fixed in the Jacobian (it is zero for paper A's analytic model, eq. 18).
//
// Density. chi2(X) = ‖r‖² + 2 (logNormalizer(θ) − logNormalizer(θ_ref)), θ_ref = 0, and logNormalizer() returns
// logNormalizer(θ_ref), so exp(−½ chi2 − logNormalizer()) is the exact density N(z; h_c(θ), Σ_c(θ)) even for a
// model whose covariance varies with θ (tabulated models); for the analytic model the correction is exactly 0.
//
// Invariants: the model is non-null, 0 ≤ c < classes(), z has the model's dimension and is finite (else
// std::invalid_argument). θ is undefined with the camera at the object's position (std::domain_error).

#include <memory>
#include <stdexcept>
#include <string>

#include "semslam/graph/Factor.h"
#include "semslam/models/Viewpoint.h"
#include "semslam/models/ViewpointClassifierModel.h"

namespace semslam {

template <class Pose>
class ViewpointSemanticFactor final : public Factor {
 public:
  static constexpr int kPoseDim = Manifold<Pose>::kDim;

  ViewpointSemanticFactor(Key robot, Key object, Vector measured, int classIndex,
                          std::shared_ptr<const ViewpointClassifierModel> model, const Pose& bodyToSensor = Pose())
      : Factor({robot, object}),
        measured_(std::move(measured)),
        classIndex_(classIndex),
        model_(std::move(model)),
        bodyToSensor_(bodyToSensor) {
    if (!model_) throw std::invalid_argument("viewpoint semantic factor: no classifier model");
    if (classIndex_ < 0 || classIndex_ >= model_->classes()) {
      throw std::invalid_argument("viewpoint semantic factor: class " + std::to_string(classIndex_) +
                                  " is outside [0, " + std::to_string(model_->classes()) + ")");
    }
    if (measured_.size() != model_->dimension() || !measured_.allFinite()) {
      throw std::invalid_argument("viewpoint semantic factor: the measurement must have " +
                                  std::to_string(model_->dimension()) + " finite entries");
    }
    referenceLogNormalizer_ = model_->noiseModel(classIndex_, 0.0)->logNormalizer();
  }

  const Vector& measured() const { return measured_; }
  int classIndex() const { return classIndex_; }
  const ViewpointClassifierModel& model() const { return *model_; }
  const Pose& bodyToSensor() const { return bodyToSensor_; }

  int errorDimension() const override { return model_->dimension(); }

  /// θ at `values`.
  double viewpoint(const Values& values) const {
    return viewpointAngle(values.at<Pose>(keys()[0]).compose(bodyToSensor_), values.at<Pose>(keys()[1]));
  }

  void linearize(const Values& values, LinearizedFactor& out) const override {
    using PoseJacobian = MatrixN<kPoseDim, kPoseDim>;
    using AngleJacobian = MatrixN<1, kPoseDim>;
    const Pose& x = values.at<Pose>(keys()[0]);
    const Pose& object = values.at<Pose>(keys()[1]);
    PoseJacobian cameraWrtX;
    const Pose camera = x.compose(bodyToSensor_, &cameraWrtX);
    AngleJacobian thetaWrtCamera, thetaWrtObject;
    const double theta = viewpointAngle(camera, object, &thetaWrtCamera, &thetaWrtObject);
    Vector dMean;
    const Vector mean = model_->mean(classIndex_, theta, &dMean);
    const SharedNoiseModel noise = model_->noiseModel(classIndex_, theta);
    out.whitenedError = measured_ - mean;
    noise->whitenInPlace(out.whitenedError);
    Vector whitenedSlope = -dMean;  // ∂r/∂θ = −R dh/dθ
    noise->whitenInPlace(whitenedSlope);
    out.jacobians.resize(2);
    out.jacobians[0] = whitenedSlope * (thetaWrtCamera * cameraWrtX);
    out.jacobians[1] = whitenedSlope * thetaWrtObject;
    out.chi2 = out.whitenedError.squaredNorm() + 2.0 * (noise->logNormalizer() - referenceLogNormalizer_);
  }

  double chi2(const Values& values) const override {
    const double theta = viewpoint(values);
    const SharedNoiseModel noise = model_->noiseModel(classIndex_, theta);
    Vector r = measured_ - model_->mean(classIndex_, theta);
    noise->whitenInPlace(r);
    return r.squaredNorm() + 2.0 * (noise->logNormalizer() - referenceLogNormalizer_);
  }

  std::optional<double> logNormalizer() const override { return referenceLogNormalizer_; }

 private:
  Vector measured_;
  int classIndex_;
  std::shared_ptr<const ViewpointClassifierModel> model_;
  Pose bodyToSensor_;
  double referenceLogNormalizer_ = 0.0;
};

}  // namespace semslam
