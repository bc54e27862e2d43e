#pragma once
// Aligning an estimated trajectory to a reference before measuring its error, as evo does (evo/core/trajectory.py
// PosePath3D.align and align_origin; evo_ape/evo_rpe options -a, -s, -as, --align_origin):
//
//   none    no change.
//   se3     Umeyama on the positions without scale (SimilarityTransform with c = 1): T_i <- [R t] T_i.
//   sim3    Umeyama with scale: first t_i <- c t_i (rotations unchanged), then T_i <- [R t] T_i.
//   scale   scale only (evo's -s without -a): t_i <- c t_i, c from the Sim(3) Umeyama, R and t discarded.
//   origin  the first poses coincide: T_i <- (T_ref,0 T_est,0⁻¹) T_i (evo's align_origin; inverse = [Rᵀ, −Rᵀt]).
//
// The poses of `estimate` and `reference` correspond by index (associate first). All poses are used.

#include <string>

#include "semslam/models/Trajectory.h"
#include "semslam/eval/Umeyama.h"

namespace semslam {

enum class AlignmentMode { None, Se3, Sim3, Scale, Origin };

/// "none" | "se3" | "sim3" | "scale" | "origin"; anything else throws InputError.
AlignmentMode parseAlignmentMode(const std::string& name);
std::string toString(AlignmentMode mode);

/// Aligns `estimate` in place to `reference` (same size) and returns the similarity applied:
/// new t_i = scale * rotation * t_i + translation, new R_i = rotation * R_i. Throws InputError for different sizes,
/// empty trajectories, or a degenerate Umeyama problem.
SimilarityTransform alignTrajectory(Trajectory& estimate, const Trajectory& reference, AlignmentMode mode);

}  // namespace semslam
