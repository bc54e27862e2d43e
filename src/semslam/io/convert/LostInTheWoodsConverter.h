#pragma once
// UTIAS "Lost in the Woods" (Barfoot's AER1513 dataset 2, as text in ../shared/data/utias-lost-in-the-woods) to a
// measurement log. Details and measured noise: docs/datasets.md.
//
// Files read from the folder: odometry.txt (t v ω), groundtruth.txt (t x y θ valid), landmarks_groundtruth.txt
// (id x y), measurements.txt (t id range bearing), params.txt (d, r_var, b_var, v_var, om_var).
//
// Frames and units: 2D, metres, radians, seconds (the dataset's time stamps, 0 to 1260.8 s). Poses are the robot
// centre in the Vicon world frame; the laser is d = 0.219 m ahead of it along the body x axis (sensor
// body_to_sensor = (d, 0, 0)); range and bearing are measured from the laser, bearing about its x axis.
//
// What it does
//   - one step per odometry time stamp (10 Hz, 12,609 steps);
//   - the odometry from step k−1 to k is the unicycle increment (UnicycleModel) of the speed and turn rate of row
//     k−1 held over t_k − t_{k−1} (the velocity stamped t_{k−1} describes the interval after it: this fits the
//     Vicon motion better than Barfoot's u_k, docs/datasets.md), covariance from σ_v² = v_var and σ_ω² = om_var
//     plus UnicycleModel's default floor (lateral slip 1e-4 m²/s);
//   - each measurement becomes a detection at the step of its time stamp: geometry (range, bearing), covariance
//     diag(r_var, b_var), truth = its landmark id (1..17);
//   - the true pose comes from groundtruth.txt where valid = 1 and is absent where valid = 0 (Vicon dropout);
//   - landmark truth: the 17 tubes, ids 1..17;
//   - sensor: range-bearing, field of view 4π/3 (the ±120° scan of the laser: observed bearings reach ±2.096 rad),
//     max range unlimited (observed ranges 0.39..5.64 m).
// Every measurement is kept. A measurement whose time matches no odometry stamp, an unknown landmark id, a
// groundtruth.txt whose time stamps differ from odometry.txt's, or a malformed row throws InputError(file, line).

#include <string>

#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

MeasurementLog convertLostInTheWoods(const std::string& folder, const ConvertOptions& options,
                                     ConversionStats* stats = nullptr);

}  // namespace semslam
