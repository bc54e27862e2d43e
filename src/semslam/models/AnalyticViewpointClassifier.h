#pragma once
// AnalyticViewpointClassifier: the viewpoint-dependent Gaussian classifier model of paper A's experiments.
//
// Math (A, sec. V, eq. 18), with s = sin²(θ/2) and θ from Viewpoint.h:
//     h_0(θ) = [ α s + (1 − α) ,  α − α s ]ᵀ       (the paper's class 1: a mirror-symmetric object, e.g. a car)
//     h_1(θ) = [ α − α s ,  α s + (1 − α) ]ᵀ       (the paper's class 2: h_0 with its two entries swapped)
//     dh_0/dθ = (α/2) sin θ · [1, −1]ᵀ,   dh_1/dθ = (α/2) sin θ · [−1, 1]ᵀ      (d sin²(θ/2)/dθ = sin θ / 2)
//     Σ_c = (RᵀR)⁻¹,  R = K [[1, −0.5], [0, 1]],  i.e.  Σ_c = (1/K²) [[1.25, 0.5], [0.5, 1]]   for both classes.
//   h_0(0) = (1 − α, α), h_0(π/2) = (1 − α/2, α/2), h_0(π) = (1, 0): each entry stays in [0, 1] and the two sum to
//   one (a class-probability vector) for α ∈ [0, 1]. Defaults α = 0.25, K = 15 (the paper's).
//
// Decisions (docs/models.md)
//   - Classes are 0-based: class 0 is the paper's class 1, class 1 the paper's class 2.
//   - The paper defines h for its class 1 only; class 2 is taken as the same model with the two entries of the mean
//     swapped. Σ_c is the paper's single (RᵀR)⁻¹ for both classes, as written (not permuted along with the mean),
//     so P(z | c = 0) and P(swap(z) | c = 1) differ slightly; |Σ_c| is the same, so the log-normalisers agree.
//   - The model is defined for M = 2 classes only: the constructor throws std::invalid_argument for M ≠ 2 (a
//     problem with other M needs a tabulated or learned model).
//
// Invariants: α ∈ [0, 1], K > 0 and finite (else std::invalid_argument).

#include "semslam/models/ViewpointClassifierModel.h"

namespace semslam {

class AnalyticViewpointClassifier final : public ViewpointClassifierModel {
 public:
  static constexpr double kDefaultAlpha = 0.25;
  static constexpr double kDefaultSharpness = 15.0;

  /// α: viewpoint dependency strength; sharpness: K; classes: M, which must be 2.
  explicit AnalyticViewpointClassifier(double alpha = kDefaultAlpha, double sharpness = kDefaultSharpness,
                                       int classes = 2);

  double alpha() const { return alpha_; }
  double sharpness() const { return sharpness_; }

  int classes() const override { return 2; }
  int dimension() const override { return 2; }
  Vector mean(int classIndex, double theta, Vector* dMeanDTheta = nullptr) const override;
  Matrix covariance(int classIndex, double theta) const override;
  SharedNoiseModel noiseModel(int classIndex, double theta) const override;

 private:
  double alpha_;
  double sharpness_;
  SharedNoiseModel noise_;  // R = K [[1, −0.5], [0, 1]], shared by both classes
};

}  // namespace semslam
