#pragma once
// SE(2) alignment: the least-squares rigid motion of the plane (a rotation about z and a planar translation)
// taking one 2D point set onto another. It is Umeyama's method (see Umeyama.h) restricted to the plane, without
// scale, and in closed form:
//
//   given corresponding points x_i, y_i ∈ R² (i = 1..n), minimise Σ_i ‖y_i − (R(φ) x_i + t)‖² over φ, t:
//   μ_x = 1/n Σ x_i,  μ_y = 1/n Σ y_i,  x̃_i = x_i − μ_x,  ỹ_i = y_i − μ_y
//   Σ_i ‖ỹ_i − R x̃_i‖² = const − 2 Σ_i ỹ_iᵀ R(φ) x̃_i = const − 2 (a cos φ + b sin φ), with
//     a = Σ_i x̃_i · ỹ_i            (= tr Σ_xy · n, Σ_xy the cross-covariance of Umeyama's eq. 38)
//     b = Σ_i x̃_i × ỹ_i = Σ_i (x̃_ix ỹ_iy − x̃_iy ỹ_ix)
//   so φ = atan2(b, a) and t = μ_y − R(φ) μ_x.
// This equals the SVD solution R = U S Vᵀ of the 2x2 Σ_xy with S = diag(1, det U det V), the best proper
// rotation; unlike 3D Umeyama it needs only two distinct points (collinear points are fine in the plane).
//
// Degenerate input (fewer than two distinct points in either set, or a = b = 0 so that every rotation fits
// equally well, judged relative to the spread: √(a² + b²) ≤ 1e-12 √(Σ‖x̃_i‖² Σ‖ỹ_i‖²)) throws InputError.

#include <Eigen/Core>

#include "semslam/eval/Umeyama.h"

namespace semslam {

/// Aligns x onto y (both 2 x n, same n ≥ 1): y ≈ R x + t with R a rotation about z. Returned as a
/// SimilarityTransform (3x3 rotation about z, translation with z = 0, scale 1) so that 2D and 3D alignments share
/// one type; apply it to a 2D point p as (R p)_xy + t_xy.
SimilarityTransform planarRigidAlignment(const Eigen::Matrix2Xd& x, const Eigen::Matrix2Xd& y);

}  // namespace semslam
