#pragma once
// KITTI tracking sequences (../shared/data/kitti-tracking, sequences 0000-0010; its SOURCE.txt) to a 3D measurement
// log with a real detector's output (issue 11; docs/datasets.md, "KITTI tracking", which has the measured counts,
// the σ(r) fit and the thresholds).
//
// Files: KittiTrackingFiles.h. Frames: KittiFrames.h (camera x right, y down, z forward → body x forward, y left,
// z up; world = the body frame of the first camera pose). Units: metres, radians, seconds; frame k is at time
// k / 10 s (10 Hz).
//
// What it does
//   - one step per frame of the pose file;
//   - reference trajectory: the step's `true_pose` is ORB-SLAM3's pose in body axes, T_wb,k = S T_c₀c,k S⁻¹. It is
//     an ESTIMATE (stereo visual odometry with its own drift), not ground truth: trajectory errors against it
//     measure recovery of the reference, and with `orbslam` odometry a dead-reckoning run scores 0 (the odometry
//     is made of it);
//   - odometry: the increment T_wb,k−1⁻¹ T_wb,k with the per-frame covariance kKittiOrbSlamSigmas² (diagonal,
//     body axes), ORB-SLAM's own relative-pose error on KITTI odometry 00 (evo-testdata: KITTI_00_ORB against
//     KITTI_00_gt, one-frame pairs; python/kitti_tracking_fit.py). With `noisy` the increment is further
//     multiplied by Exp(δ), δ ~ N(0, K² Σ) drawn from std::mt19937(seed) in step order (models/Sampling.h), and
//     the stated covariance is (1 + K²) Σ: the ORB-SLAM3 error plus the added noise, as paper B's robustness
//     study adds noise to real odometry;
//   - detections: every PointRCNN row of the frame whose score is at least its class's threshold (defaults
//     kKittiDefaultScoreThresholds) and, with --max-range R, whose range is at most R; Car, then Pedestrian, then
//     Cyclist file order. Geometry: relative-position [x, y, z], the box's bottom centre in the body (= sensor)
//     frame; covariance Σ(p) aligned to the viewing ray (KittiDetectionNoise.h); label: the detector's class
//     (0 Car, 1 Pedestrian, 2 Cyclist); truth: KittiTrackingTruth.h (a static track's id, not-a-landmark for a
//     moving track — with the track id as `clutter_source` — or a false positive, unknown otherwise);
//   - semantic model: categorical with the misclassification rate p estimated from the matched detections whose
//     label is one of the detector's classes: p = (off-diagonal count + 1) / (total + 3) (add-one smoothing, so
//     p > 0), from this sequence's matches or from the counts of --confusion FILE (a held-out estimate);
//   - landmark truth: each static track that some detection has as truth, with the class of its label and its
//     mean world position;
//   - sensor: relative-position, body_to_sensor the identity, field of view kKittiFieldOfView (the camera's
//     horizontal opening; detections and labels are limited to the image), max range --max-range (0: none);
//   - the common tail (ConversionCommon.h): keyframing, --max-steps, the initial pose prior at the first reference
//     pose; --classes and --misclassification are rejected (the detector's labels are kept).
// Deterministic: the same files and arguments give the same log, byte for byte.
// Bad input throws InputError(file, line, problem) (KittiTrackingFiles.h), and bad options InputError(problem).

#include <array>
#include <string>

#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// Per-frame (10 Hz) standard deviations of ORB-SLAM's relative-pose error in body axes (x, y, z in metres,
/// rx, ry, rz in radians): the 95 % quantile of |e − median(e)| over the 4,540 one-frame pairs of evo-testdata's
/// KITTI_00_ORB against KITTI_00_gt, divided by 1.96, rounded up (docs/datasets.md).
inline constexpr std::array<double, 6> kKittiOrbSlamSigmas = {0.017, 0.014, 0.0081, 0.00070, 0.00074, 0.00058};
/// Default score thresholds (Car, Pedestrian, Cyclist): the score that maximises F1 of matched against unmatched
/// detections over sequences 0000-0010 (docs/datasets.md; python/kitti_tracking_fit.py).
/// Measured: Car 1.873 (F1 0.934), Pedestrian 2.773 (F1 0.526), Cyclist 3.746 (F1 0.791), rounded down.
inline constexpr std::array<double, 3> kKittiDefaultScoreThresholds = {1.87, 2.77, 3.74};
/// The horizontal field of view of KITTI's colour camera, 2 atan(621 / 721.5377) (image width 1242 px).
inline constexpr double kKittiFieldOfView = 1.4323;
/// Seconds between frames.
inline constexpr double kKittiFramePeriod = 0.1;

MeasurementLog convertKittiTracking(const std::string& folder, const ConvertOptions& options,
                                    ConversionStats* stats = nullptr);

}  // namespace semslam
