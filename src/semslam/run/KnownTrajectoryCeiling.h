#pragma once
// KnownTrajectoryCeiling: what association alone could reach on a log (issue 10's "ceiling"). The same front end and
// method run on a copy of the log whose poses are pinned to the known-association estimate, so every association
// error left is the front end's, not the coupling with a drifting trajectory:
//
//   1. run `known` on the log: trajectory x̂_0..x̂_N, its final graph and (for independent pose errors) the marginal
//      covariances Σ_k;
//   2. optionally move the poses by a draw inside their uncertainty, s the pose-error scale (0: none), seeded:
//      - joint (the default): the whole trajectory drawn from the known-association posterior at x̂, scaled,
//        X̃ = X̂ ⊕ s δ, δ ~ N(0, H⁻¹) (models/PosteriorSampler.h): consecutive poses err together as the estimate's
//        do, so this is what association reaches with poses as uncertain as the known-association ones;
//      - independent: each pose alone, x̃_k = x̂_k ⊕ s L_k n_k with L_k L_kᵀ = Σ_k, n_k ~ N(0, I)
//        (models/Sampling.h): consecutive poses err independently, √2 s σ_k apart at every step (the whole drift's
//        uncertainty between neighbours), far beyond the posterior's relative errors;
//   3. replace the log's initial pose prior by x̃_0 and every odometry increment by x̃_{k−1}⁻¹ x̃_k, each with the
//      covariance σ² I, σ = kPinnedSigma (so tight that the poses stay where they are put, yet well-conditioned
//      beside the detections' noise);
//   4. run the method on that log; its metrics are scored against the original truth as usual.
//
// The result is named "<method>@known-trajectory". Detections, labels and truth are untouched.

#include <cstdint>
#include <vector>

#include "semslam/models/MeasurementLog.h"
#include "semslam/run/RunMethod.h"

namespace semslam {

/// Standard deviation of the pinned poses' odometry and prior, per tangent axis (m and rad).
inline constexpr double kPinnedSigma = 1e-4;

/// `log` with its initial pose prior at trajectory[0] and every odometry the motion between consecutive poses of
/// `trajectory` (one per step), covariance kPinnedSigma² I. Throws std::invalid_argument when the sizes differ.
MeasurementLog logOnTrajectory(const MeasurementLog& log, const std::vector<Pose>& trajectory);

/// Each pose moved by scale · L_k n_k in its tangent (right perturbation), n_k drawn from a std::mt19937 seeded with
/// `seed`; scale 0 returns the trajectory unchanged without drawing.
std::vector<Pose> perturbedTrajectory(const std::vector<Pose>& trajectory, const std::vector<Matrix>& covariances,
                                      double scale, std::uint32_t seed);

/// How step 2 draws the pose errors.
enum class PoseErrorDraw { Joint, Independent };

/// Steps 1-4 above for `options.method` (paper B's methods; the hybrid belief takes no ceiling: std::invalid_argument).
MethodRun runOnKnownTrajectory(const MeasurementLog& log, const MethodOptions& options, double poseErrorScale,
                               std::uint32_t seed, PoseErrorDraw draw = PoseErrorDraw::Joint);

}  // namespace semslam
