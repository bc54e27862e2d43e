#pragma once
// KITTI's camera frame and semslam's body frame (docs/datasets.md, "KITTI tracking", Frames).
//
//   camera frame c (KITTI's rectified left camera):  x right, y down, z forward;
//   body frame b (semslam, as a vehicle user expects): x forward, y left, z up, origin at the camera.
// The rotation taking camera coordinates to body coordinates is the constant
//       R_bc = [[0, 0, 1], [−1, 0, 0], [0, −1, 0]]      (b_x = c_z, b_y = −c_x, b_z = −c_y),
// a proper rotation (det +1). The log's world frame w is the body frame of the first camera frame c₀ (KITTI's world:
// ORB-SLAM3 starts at the identity), so with S = (R_bc, 0) ∈ SE(3):
//       body pose      T_wb,k = S · T_c₀c,k · S⁻¹        (ORB-SLAM3 camera-to-world T_c₀c,k, conjugated)
//       a point        p_b = R_bc · p_c                  (a label's or a detection's bottom centre)
//       in the world   p_w = T_wb,k · p_b = S · T_c₀c,k · p_c.
// Hence a label's world position through the body pose equals the one through the camera pose rotated by S, and
// relative motions T_wb,k−1⁻¹ T_wb,k = S (T_c₀c,k−1⁻¹ T_c₀c,k) S⁻¹ are the camera's, expressed in body axes. The
// sensor is the camera, at the body's origin (body_to_sensor the identity), so a detection's geometry is p_b.

#include "semslam/geometry/SE3.h"

namespace semslam {

/// R_bc as an SE(3) without translation: S above.
const SE3& kittiCameraToBody();

/// p_b = R_bc · p_c.
Point3 kittiBodyPoint(const Point3& cameraPoint);

/// T_wb = S · T_c₀c · S⁻¹.
SE3 kittiBodyPose(const SE3& cameraToWorld);

}  // namespace semslam
