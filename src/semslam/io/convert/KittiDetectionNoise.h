#pragma once
// The noise of a PointRCNN detection's position (docs/datasets.md, "KITTI tracking", σ(r)).
//
// Model: the detected bottom centre p (body frame, range r = ‖p‖, viewing ray u = p / r) is the true one plus a
// zero-mean Gaussian error whose standard deviation grows linearly with range, separately along the ray and across
// it:
//       σ_radial(r)  = a_radial  + b_radial  · r,
//       σ_lateral(r) = a_lateral + b_lateral · r      (the same in both directions across the ray),
//       Σ(p) = σ_radial² u uᵀ + σ_lateral² (I − u uᵀ),
// so Σ is symmetric positive definite for every p ≠ 0 (eigenvalues σ_radial² once, σ_lateral² twice) and is the
// same in the camera and body frames (a rotation maps u uᵀ and I to their rotated selves).
//
// The constants are fitted against the labels of sequences 0000-0010 (Car detections matched to Car labels, the
// converter's own matching): per 10 m range bin the stated σ is the 95 % quantile of |e − median(e)| divided by
// 1.96 (the calibration the other converters use: the Gaussian then holds as many residuals as a Gaussian would),
// and (a, b) is the count-weighted least-squares line through the bins. python/kitti_tracking_fit.py reproduces
// the fit from `semslam convert kitti-tracking ... --matches-out` files; docs/datasets.md has the bins and the
// residuals of the line.

#include "semslam/geometry/Matrix.h"

namespace semslam {

struct KittiRangeSigma {
  double a = 0.0;  ///< metres
  double b = 0.0;  ///< metres per metre of range

  double at(double range) const { return a + b * range; }
};

/// Fit over 12,311 Car-on-Car matches: radial 0.0298 + 0.00476 r, lateral 0.0375 + 0.00173 r (rounded up).
inline constexpr KittiRangeSigma kKittiRadialSigma{0.030, 0.0048};
inline constexpr KittiRangeSigma kKittiLateralSigma{0.038, 0.0018};

/// Σ(p) above; throws std::invalid_argument for p = 0 or a non-finite p.
Matrix3 kittiDetectionCovariance(const Vector3& bodyPoint, const KittiRangeSigma& radial = kKittiRadialSigma,
                                 const KittiRangeSigma& lateral = kKittiLateralSigma);

}  // namespace semslam
