#pragma once
// The trajectory part of metrics.json: absolute position error (ATE) and absolute rotation error of an estimated
// trajectory against the true one, after a rigid alignment, with evo's statistics (ErrorStatistics.h).
//
// Poses correspond by index (one per time step of a measurement log). With estimate P_i = (R_i, p_i) and truth
// Q_i = (S_i, q_i):
//   alignment A = (R_A, t_A): 2D  SE(2) Umeyama on the positions (PlanarAlignment.h: rotation about z only),
//                             3D  SE(3) Umeyama on the positions (Umeyama.h without scale, as evo's -a);
//                             or the identity when alignment is off.
//   ATE:       e_i = ‖R_A p_i + t_A − q_i‖₂                         (metres)
//   rotation:  r_i = |angle(S_i⁻¹ R_A R_i)| ∈ [0, π]                 (radians)
//              2D: |wrap(θ_A + θ_i − θ_ref,i)|;  3D: the axis-angle magnitude, computed as PoseRelation.h's
//              rotationAngle (scipy's as_rotvec norm, accurate for small angles).
// Statistics of e and of r as ErrorStatistics (rmse, mean, median, max, min, sse, population std).
//
// The alignment is estimated from positions only (never from headings), so it is the transform evo's
// `--align se3` would apply; in 2D it stays in the plane. Throws InputError for different sizes, an empty
// trajectory, mixed 2D/3D poses, or a degenerate alignment (see PlanarAlignment.h / Umeyama.h).

#include <cstddef>
#include <vector>

#include "semslam/eval/ErrorStatistics.h"
#include "semslam/eval/Umeyama.h"
#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

struct TrajectoryErrors {
  int dimension = 2;                    ///< 2 (SE2 poses) or 3 (SE3 poses)
  bool aligned = false;                 ///< whether the rigid alignment was applied
  SimilarityTransform alignment;        ///< applied to the estimate (identity when not aligned; scale is 1)
  ErrorStatistics translation;          ///< of the position errors e_i, metres
  ErrorStatistics rotation;             ///< of the rotation errors r_i, radians
  std::vector<double> translationErrors;
  std::vector<double> rotationErrors;
};

TrajectoryErrors evaluateTrajectoryErrors(const std::vector<SE2>& estimate, const std::vector<SE2>& reference,
                                          bool align = true);
TrajectoryErrors evaluateTrajectoryErrors(const std::vector<SE3>& estimate, const std::vector<SE3>& reference,
                                          bool align = true);
/// Poses from a measurement log or a method: all SE2 or all SE3 (both vectors alike).
TrajectoryErrors evaluateTrajectoryErrors(const std::vector<Pose>& estimate, const std::vector<Pose>& reference,
                                          bool align = true);

/// The rigid alignment the functions above use, on its own: SE(2) Umeyama of the planar positions.
SimilarityTransform alignPlanarTrajectory(const std::vector<SE2>& estimate, const std::vector<SE2>& reference);
/// SE(3) Umeyama of the positions (no scale).
SimilarityTransform alignSpatialTrajectory(const std::vector<SE3>& estimate, const std::vector<SE3>& reference);

}  // namespace semslam
