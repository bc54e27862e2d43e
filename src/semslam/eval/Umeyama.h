#pragma once
// Least-squares similarity transform between two point sets: Umeyama, "Least-squares estimation of transformation
// parameters between two point patterns", IEEE PAMI 13(4), 1991; exactly as evo's geometry.umeyama_alignment.
//
// Given corresponding points x_i, y_i (i = 1..n, the columns of x and y), find R ∈ SO(3), t, c > 0 minimising
//   Σ_i ‖y_i − (c R x_i + t)‖²:
//   μ_x = 1/n Σ x_i,  μ_y = 1/n Σ y_i                           (eq. 34, 35)
//   σ_x² = 1/n Σ ‖x_i − μ_x‖²                                    (eq. 36)
//   Σ_xy = 1/n Σ (y_i − μ_y)(x_i − μ_x)ᵀ = U D Vᵀ  (SVD)         (eq. 38)
//   S = I, or diag(1, 1, −1) when det(U) det(V) < 0              (eq. 43; keeps R a proper rotation)
//   R = U S Vᵀ                                                   (eq. 40)
//   c = tr(D S) / σ_x²  (with scale; otherwise c = 1)            (eq. 42)
//   t = μ_y − c R μ_x                                            (eq. 41)
// so that y ≈ c R x + t. Like evo, fewer than 2 singular values above machine epsilon (all points on one line or
// one point) is degenerate and throws InputError.

#include "semslam/geometry/Matrix.h"

#include <Eigen/Core>

namespace semslam {

struct SimilarityTransform {
  Matrix3 rotation = Matrix3::Identity();
  Vector3 translation = Vector3::Zero();
  double scale = 1.0;

  /// y = scale * rotation * x + translation
  Vector3 apply(const Vector3& x) const { return scale * (rotation * x) + translation; }
};

/// Aligns x onto y (both 3 x n, n >= 1, same size). withScale = false fixes c = 1 (SE(3) alignment).
SimilarityTransform umeyamaAlignment(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y, bool withScale);

}  // namespace semslam
