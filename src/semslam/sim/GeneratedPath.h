#pragma once
// GeneratedPath: the trajectories the semantic simulator generates when no file is given (`--path`), in 2D
// (SE2) or 3D (SE3), with a constant distance between consecutive poses. docs/simulators.md shows both.
//
// loop (seeded): a closed, smooth, randomly shaped loop driven `loops` times, so that every place is revisited
//   (loop closures, and the data association problem they bring). In polar form about its centre
//       r(φ) = 1 + Σ_{j=2..4} a_j cos(j φ + p_j),   a_j = 0.1 u,  p_j = 2π u   (u: uniform01 draws, Path stream)
//   and in 3D a height z(φ) = h sin(2φ + p_z) (h = heightAmplitude); the curve (a polyline of 4096 points) is
//   then scaled so that its length is exactly steps · stepLength / loops, and the poses are taken at arc
//   lengths k · stepLength (k = 0..steps, wrapping around the loop), linearly interpolated along the polyline.
// lawnmower (deterministic): back-and-forth rows along x of length rowLength, rowSpacing apart in y, joined by
//   half circles of diameter rowSpacing; as many rows as the steps need; flat (z = 0) in 3D.
// Headings follow the path's tangent: 2D θ = atan2(t_y, t_x); 3D the body x axis is the tangent t, y = ẑ × t
// (normalised), z = x × y (no roll). Every path is moved so that it starts at the origin heading along +x (in
// 3D: its first heading's yaw is removed, z stays up). Times are k · timeStep.
//
// Invariants: dimension 2 or 3, steps ≥ 1, stepLength > 0, loops ≥ 1, rowLength > 0, rowSpacing > 0,
// heightAmplitude ≥ 0, timeStep > 0, all finite (else std::invalid_argument).

#include <random>
#include <string>

#include "semslam/sim/SimTrajectory.h"

namespace semslam {

enum class PathShape { Loop, Lawnmower };

struct PathOptions {
  PathShape shape = PathShape::Loop;
  int dimension = 2;
  int steps = 200;  // poses: steps + 1
  double stepLength = 1.0;
  int loops = 2;
  double rowLength = 30.0;
  double rowSpacing = 6.0;
  double heightAmplitude = 1.0;
  double timeStep = 1.0;
};

/// "loop" | "lawnmower"; anything else throws std::invalid_argument.
PathShape parsePathShape(const std::string& name);

SimTrajectory generatePath(const PathOptions& options, std::mt19937& rng);

}  // namespace semslam
