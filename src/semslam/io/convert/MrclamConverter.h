#pragma once
// UTIAS MRCLAM (multi-robot cooperative localisation and mapping; ../shared/data/mrclam/MRCLAM_Dataset6) to a
// measurement log of one robot. Details, noise values and measured residuals: docs/datasets.md.
//
// Files read from the dataset folder: Barcodes.dat (subject barcode), Landmark_Groundtruth.dat (subject x y x_sd
// y_sd), RobotN_Odometry.dat (t v ω), RobotN_Measurement.dat (t barcode range bearing), RobotN_Groundtruth.dat
// (t x y θ). RobotN_Measurement_x.dat (a derived copy) is not read: barcodes are mapped here.
//
// Frames and units: 2D, metres, radians, seconds; times are the dataset's Unix time stamps (about 1.248e9 s).
// Poses are the robot in the Vicon world frame; the camera is taken at the robot's origin (body_to_sensor the
// identity: the bearing residuals show no offset, docs/datasets.md); bearing about the robot's x axis.
//
// What it does
//   - steps at every distinct odometry or measurement time stamp (the measurement stamps split the odometry
//     intervals, so every detection sits at its own time, exactly);
//   - the command (v, ω) of an odometry row holds from its stamp (+ ConvertOptions::commandDelay, 0 by default: a
//     step starts there) until the next row's (of two rows with one stamp, the later wins; before the first row
//     the robot is at rest); each interval between steps is a unicycle
//     increment (UnicycleModel) with input noise of white intensity: σ_v² = kMrclamVelocityIntensity / dt,
//     σ_ω² = kMrclamTurnRateIntensity / dt (so the covariance grows with time, not with the number of stamps, and
//     splitting an interval does not change it), plus a floor of intensities (1e-6, kMrclamLateralIntensity,
//     1e-6) (UnicycleModel's default with the measured lateral slip);
//   - every measurement row becomes a detection at its stamp: (range, bearing) with covariance
//     diag(kMrclamRangeSigma², kMrclamBearingSigma²); the barcode is mapped through Barcodes.dat; a landmark
//     (subjects 6..20, those of Landmark_Groundtruth.dat) gives truth = its subject number; another robot's
//     barcode (subjects 1..5) or a barcode not in Barcodes.dat gives truth "not a landmark": such rows are kept,
//     never dropped;
//   - the true pose at a step is the Vicon pose interpolated (constant twist, SE2::interpolate) between the two
//     ground-truth samples around it when they are at most kMrclamMaxTruthGap apart, absent otherwise (outside
//     the ground truth's time span, across Vicon gaps);
//   - landmark truth: the 15 landmarks of Landmark_Groundtruth.dat (their sub-millimetre std-devs are ignored);
//   - sensor: range-bearing, field of view 1.2 rad (observed bearings ±0.59 rad), max range unlimited
//     (observed ranges 0.94..8.6 m).
// A malformed row, a robot other than 1..5, or a missing file throws InputError(file, line).

#include <string>

#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// Measurement noise, calibrated so that the stated Gaussian holds as many residuals as a Gaussian would: σ is the
/// 95 % quantile of |residual − median| over all landmark detections of Dataset 6's five robots against the Vicon
/// truth (15,383 residuals: 0.406 m and 0.0268 rad) divided by 1.96, i.e. 0.207 m and 0.0137 rad, rounded up. The
/// robust standard deviations (1.4826 · MAD: 0.131 m, 0.0083 rad) describe only the core of these heavy-tailed
/// residuals; stated as σ they made true landmarks lose to the unassigned hypothesis, which split and merged
/// landmarks even on the true trajectory (docs/association-front-end.md §9).
inline constexpr double kMrclamRangeSigma = 0.21;     // metres
inline constexpr double kMrclamBearingSigma = 0.014;  // radians
/// Odometry input noise intensities (variance per second): the variance, over one second, of the commanded
/// motion's error against the Vicon motion, pooled over the five robots of Dataset 6 (forward 0.0116 m, heading
/// 0.040 rad per second), and the lateral slip intensity (0.002 m per second) that replaces UnicycleModel's
/// default floor in y.
inline constexpr double kMrclamVelocityIntensity = 1.4e-4;  // (m/s)² · s
inline constexpr double kMrclamTurnRateIntensity = 1.6e-3;  // (rad/s)² · s
inline constexpr double kMrclamLateralIntensity = 4e-6;     // m²/s
/// The largest command delay the converter takes (seconds): ten times the measured 0.2 s.
inline constexpr double kMrclamMaxCommandDelay = 2.0;
/// Ground-truth samples further apart than this are not interpolated between (seconds).
inline constexpr double kMrclamMaxTruthGap = 0.5;

MeasurementLog convertMrclam(const std::string& folder, const ConvertOptions& options,
                             ConversionStats* stats = nullptr);

}  // namespace semslam
