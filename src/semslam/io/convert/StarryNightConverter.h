#pragma once
// UTIAS "Starry Night" (Barfoot's AER1513 dataset 3, as text in ../shared/data/utias-starry-night) to a 3D
// measurement log. Details, the covariance model and measured residuals: docs/datasets.md.
//
// Files read from the folder: imu_velocities.txt (t ωx ωy ωz vx vy vz), groundtruth.txt (t θ(3) r(3)),
// landmarks_groundtruth.txt (id x y z), calibration.txt (fu fv cu cv b C_c_v ρ_v_c_v w_var v_var y_var),
// rbe_measurements_vehicle_frame.txt (k t id range bearing elevation px py pz) and stereo_measurements.txt
// (k t id ul vl ur vr), the latter row-aligned with the former.
//
// Frames and units: 3D, metres, radians, seconds (the dataset's stamps, 0 to 168.9 s). Poses are the vehicle
// frame v_k in the inertial (Vicon) frame i: T = (C_vk_i⁻¹, r_i_vk_i) with C_vk_i = Exp(θ)ᵀ (Barfoot's axis-angle
// convention: C_vk_i = cos a I + (1 − cos a) uuᵀ − sin a u^). Range, bearing and elevation are those of the
// triangulated point expressed in the VEHICLE frame (the file's own derivation: p_v = C_c_vᵀ p_c + ρ_v_c_v), so
// the sensor's body_to_sensor is the identity; the camera looks along the vehicle's −x axis, so bearings are near
// ±π (field of view: 0, all around, because the log's field of view is centred on the sensor's +x axis).
//
// What it does
//   - one step per velocity time stamp (1,900 steps);
//   - the odometry from step k−1 to k is Exp(dt (v_k, ω_k)) (VelocityModel3; Barfoot's model: the velocity
//     stamped t_k over t_k − t_{k−1}, which fits the Vicon motion better than the row before), input covariance
//     diag(v_var, w_var) (reordered translation first), no floor;
//   - each rbe row becomes a detection at step k: geometry (range, bearing, elevation); covariance the
//     first-order propagation, through the stereo triangulation, the vehicle-frame transform and (r, b, e), of a
//     4×4 pixel covariance whose diagonal is the stated y_var and whose correlations are kStereoPixelCorrelation
//     (measured against ground truth; the stated variances alone, taken as independent, overstate the range
//     noise about threefold, docs/datasets.md); truth = its landmark id (1..20);
//   - the true pose at every step from groundtruth.txt; landmark truth: the 20 points.
// Every measurement is kept. Misaligned files (rbe vs stereo rows, ground truth vs velocity stamps), a step index
// or time that matches no step, an unknown landmark id, or a malformed row throws InputError(file, line).

#include <array>
#include <string>

#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// Correlations of the stereo pixel errors (ul, vl, ur, vr), from the 9,410 pixel residuals against ground truth
/// (the pixels predicted from the Vicon pose and landmark with the calibration): row-major 4×4.
// clang-format off
inline constexpr std::array<double, 16> kStereoPixelCorrelation = {
    1.0,    0.1449, 0.8600, 0.1428,  //
    0.1449, 1.0,    0.1580, 0.9875,  //
    0.8600, 0.1580, 1.0,    0.1603,  //
    0.1428, 0.9875, 0.1603, 1.0};
// clang-format on

MeasurementLog convertStarryNight(const std::string& folder, const ConvertOptions& options,
                                  ConversionStats* stats = nullptr);

}  // namespace semslam
