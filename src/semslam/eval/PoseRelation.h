#pragma once
// Which part of a pose error a metric measures: evo's PoseRelation (evo/core/metrics.py) and the -r option of
// evo_ape / evo_rpe. For an error pose E = [R_E t_E; 0 1]:
//
//   trans_part  ‖t_E‖₂ (metres)                 the default of evo_ape and evo_rpe
//   angle_rad   |θ(R_E)|, θ the angle of the axis-angle (log) of R_E, in [0, π]   (radians)
//   angle_deg   the same in degrees (θ · 180/π)
//   rot_part    ‖R_E − I‖_F (dimensionless)
//   full        ‖E − I₄‖_F (dimensionless)
//
// The angle is computed as evo does since it uses scipy (so3_log_angle = ‖Rotation.from_matrix(R).as_rotvec()‖):
// quaternion from the matrix by the largest-diagonal method, normalised, then θ = 2 atan2(‖q_xyz‖, |q_w|). This
// stays accurate for small angles, unlike acos((tr R − 1)/2).

#include <string>

#include "semslam/geometry/Matrix.h"

namespace semslam {

enum class PoseRelation { TranslationPart, AngleRad, AngleDeg, RotationPart, Full };

/// "trans_part" | "angle_deg" | "angle_rad" | "rot_part" | "full"; anything else throws InputError.
PoseRelation parsePoseRelation(const std::string& name);
std::string toString(PoseRelation relation);
/// "m", "deg", "rad" or "" (dimensionless), as evo's unit of the relation.
std::string unitOf(PoseRelation relation);

/// The scalar error of the error pose `e` under `relation`.
double poseErrorValue(const Matrix4& e, PoseRelation relation);

/// The rotation angle θ ∈ [0, π] of a (nearly) orthonormal 3x3 matrix, as scipy's as_rotvec norm.
double rotationAngle(const Matrix3& r);

}  // namespace semslam
