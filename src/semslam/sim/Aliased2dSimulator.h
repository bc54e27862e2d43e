#pragma once
// Aliased2dSimulator: measurement logs of paper A's aliased scenario (sec. V): ground-truth tracks sampled from
// one fixed start (Fig. 3b), with the paper's motion model, range-bearing sensor with a limited field of view, and
// viewpoint-dependent Gaussian classifier scores (eq. 18). docs/simulators.md describes the model in full.
//
// One track of K steps (track t of a run with user seed S; every quantity from its own SimulationStreams stream):
//   step 0:  time 0, the true start x_0 = scenario.start, no odometry, no detections (paper A measures Z_k from
//            k = 1 on, after the first action a_0).
//   step k:  a_{k−1} = policy(x_{k−1})             the commanded action (aliased2dControl: random turns, back
//                                                  toward the arena, clear of the objects)
//            x_k = x_{k−1} · a_{k−1} · Exp(w),  w ~ N(0, Σ_w)      the true motion (A: N(f(x, a), Σ_w))
//            odometry = (a_{k−1}, Σ_w): what the robot knows it did, with the motion model's covariance
//            for every object o visible from x_k (VisibilityModel2: field of view and maximum range), in the
//            scenario's order: one detection with
//              geometry  z = h(x_k, t_o) + v, v ~ N(0, Σ_v)      (MeasurementSampling.h; dropped if range ≤ 0)
//              scores    z_sem ~ N(h_c(θ), Σ_c), θ = viewpointAngle(x_k · s, x_o), c the object's true class
//              truth     the object's id
//            listed by increasing measured bearing; time k · time_step; true pose x_k.
// Header: dimension 2, classes M, semantic "scores", classifier viewpoint-gaussian (alpha, K), the sensor,
// landmarks_have_pose (objects are SE2 poses), the initial pose prior N(mean, Σ_p) and the object priors
// N(mean_o, Σ_o), each mean either drawn around the truth (mean = truth · Exp(δ), δ ~ N(0, Σ)) or the truth itself
// (scenario.priors.poseMean, objectMeans), and the landmark truth (ids, classes, poses).

#include <cstdint>
#include <random>

#include "semslam/models/MeasurementLog.h"
#include "semslam/sim/Aliased2dScenario.h"

namespace semslam {

/// The commanded action of the track-sampling policy at the true pose `pose`: Exp((d, 0, Δθ)), an arc of length
/// d = stepLength turning by Δθ. Proposals, each taking one uniform01 draw u:
///   first:        inside the arena Δθ = maxTurn (2u − 1); outside it the turn toward the arena's centre, clamped
///                 to [−maxTurn, maxTurn] (u is drawn and unused);
///   then up to 16 more, Δθ = maxTurn (2u − 1);
/// the first proposal that keeps `clearance` from every object along its arc continued for three steps at the
/// same turn rate (checked every half step) is taken; when none does, the one that keeps farthest from them.
SE2 aliased2dControl(const Aliased2dScenario& scenario, const SE2& pose, std::mt19937& rng);

/// Track `track` (of `tracks`, which only enters the header's source text) with `steps` ≥ 1 steps after the
/// start, for the user seed `seed`. Throws std::invalid_argument for an invalid scenario or steps < 1.
MeasurementLog simulateAliased2dTrack(const Aliased2dScenario& scenario, std::uint64_t seed, int track, int steps,
                                      int tracks = 1);

}  // namespace semslam
