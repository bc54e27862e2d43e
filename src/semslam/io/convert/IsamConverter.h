#pragma once
// iSAM 2D landmark files (cityTrees10000-style: EDGE2/ODOMETRY and LANDMARK records with square-root information,
// ../shared/data/isam) to a measurement log. Details: docs/datasets.md.
//
// Input: the iSAM file's path, e.g. .../cityTrees10000.txt. Ground truth, where present, comes from the files
// beside it named <stem>_gt_poses_DERIVED.txt (pose_id x y θ) and <stem>_gt_landmarks_DERIVED.txt
// (landmark_id x y n_observations) (their derivation from the noise-free file is in the data folder's SOURCE.txt).
//
// Frames and units: 2D, the simulation's metres and radians; time = the pose index (seconds in name only).
// Poses are the robot in the simulation's world frame, whose origin is pose 0. A LANDMARK record is the landmark's
// Cartesian position in the frame of its pose: sensor relative-position 2D, body_to_sensor the identity.
//
// What it does
//   - one step per pose, 0..N−1: an `EDGE2 i j` (or ODOMETRY) record must join the newest pose i to the next,
//     j = i + 1; its (dx, dy, dθ) is the step's odometry increment and its covariance is (RᵀR)⁻¹ for the
//     upper-triangular square-root information R of the record (taken in the tangent of the right perturbation,
//     as the library's iSAM reader does; cityTrees' R is diagonal and isotropic in x, y, where the two agree);
//   - a `LANDMARK i l` record is a detection at step i (any pose already created): geometry (dx, dy), covariance
//     (RᵀR)⁻¹, truth = l (the simulation's own landmark id);
//   - true poses and landmark truth from the DERIVED files when they are present (their counts must match).
// Every record is kept; any other record type, a pose out of order, or a malformed record throws InputError.

#include <string>

#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

MeasurementLog convertIsam(const std::string& path, const ConvertOptions& options, ConversionStats* stats = nullptr);

}  // namespace semslam
