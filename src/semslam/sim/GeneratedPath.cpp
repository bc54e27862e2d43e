#include "semslam/sim/GeneratedPath.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "semslam/models/Sampling.h"

namespace semslam {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kLoopPoints = 4096;

/// A point of a path and its unit tangent, in 3D (z = 0 for planar paths).
struct PathPoint {
  Vector3 position;
  Vector3 tangent;
};

void check(bool ok, const std::string& problem) {
  if (!ok) throw std::invalid_argument("path: " + problem);
}

/// The closed random loop as a polyline (first point not repeated at the end), before scaling.
std::vector<Vector3> loopPolyline(const PathOptions& options, std::mt19937& rng) {
  double amplitude[3], phase[3];
  for (int j = 0; j < 3; ++j) {
    amplitude[j] = 0.1 * uniform01(rng);
    phase[j] = 2.0 * kPi * uniform01(rng);
  }
  const double heightPhase = 2.0 * kPi * uniform01(rng);
  std::vector<Vector3> points(kLoopPoints);
  for (int i = 0; i < kLoopPoints; ++i) {
    const double phi = 2.0 * kPi * i / kLoopPoints;
    double r = 1.0;
    for (int j = 0; j < 3; ++j) r += amplitude[j] * std::cos((j + 2) * phi + phase[j]);
    const double z = options.dimension == 3 ? options.heightAmplitude * std::sin(2.0 * phi + heightPhase) : 0.0;
    points[i] = Vector3(r * std::cos(phi), r * std::sin(phi), z);
  }
  return points;
}

/// Points at arc lengths k · stepLength around the closed polyline scaled to length `perimeter`.
std::vector<PathPoint> sampleLoop(const PathOptions& options, std::mt19937& rng) {
  std::vector<Vector3> points = loopPolyline(options, rng);
  const int n = static_cast<int>(points.size());
  // The horizontal shape has unit mean radius; the height is in metres: scale the horizontal part to the wanted
  // perimeter first, then the whole curve to make the 3D length exact.
  const double perimeter = options.steps * options.stepLength / options.loops;
  for (Vector3& p : points) p.head<2>() *= perimeter / (2.0 * kPi);
  std::vector<double> cumulative(n + 1, 0.0);
  for (int i = 0; i < n; ++i) cumulative[i + 1] = cumulative[i] + (points[(i + 1) % n] - points[i]).norm();
  const double scale = perimeter / cumulative[n];
  for (Vector3& p : points) p *= scale;
  for (double& c : cumulative) c *= scale;

  std::vector<PathPoint> samples;
  for (int k = 0; k <= options.steps; ++k) {
    const double s = std::fmod(k * options.stepLength, perimeter);
    int i = static_cast<int>(std::upper_bound(cumulative.begin(), cumulative.end(), s) - cumulative.begin()) - 1;
    i = std::clamp(i, 0, n - 1);
    const Vector3 a = points[i];
    const Vector3 b = points[(i + 1) % n];
    const double length = cumulative[i + 1] - cumulative[i];
    const double t = length > 0.0 ? (s - cumulative[i]) / length : 0.0;
    samples.push_back({a + t * (b - a), (b - a).normalized()});
  }
  return samples;
}

PathPoint lawnmowerPoint(const PathOptions& options, double s) {
  const double length = options.rowLength;
  const double radius = 0.5 * options.rowSpacing;
  const double unit = length + kPi * radius;  // one row and one turn
  const int row = static_cast<int>(std::floor(s / unit));
  const double u = s - row * unit;
  const double y = row * options.rowSpacing;
  const bool even = row % 2 == 0;
  if (u < length) {
    return even ? PathPoint{Vector3(u, y, 0.0), Vector3(1.0, 0.0, 0.0)}
                : PathPoint{Vector3(length - u, y, 0.0), Vector3(-1.0, 0.0, 0.0)};
  }
  const double a = (u - length) / radius;  // in [0, π]
  if (even) {                              // counter-clockwise about (length, y + radius)
    return {Vector3(length + radius * std::sin(a), y + radius - radius * std::cos(a), 0.0),
            Vector3(std::cos(a), std::sin(a), 0.0)};
  }
  // clockwise about (0, y + radius)
  return {Vector3(-radius * std::sin(a), y + radius - radius * std::cos(a), 0.0),
          Vector3(std::cos(kPi - a), std::sin(kPi - a), 0.0)};
}

SE3 poseFromPathPoint(const PathPoint& point) {
  const Vector3 x = point.tangent.normalized();
  Vector3 y = Vector3::UnitZ().cross(x);
  if (y.norm() < 1e-9) y = Vector3::UnitY();  // a vertical tangent: any horizontal y
  y.normalize();
  const Vector3 z = x.cross(y);
  Matrix3 R;
  R.col(0) = x;
  R.col(1) = y;
  R.col(2) = z;
  return SE3(SO3(R), point.position);
}

}  // namespace

PathShape parsePathShape(const std::string& name) {
  if (name == "loop") return PathShape::Loop;
  if (name == "lawnmower") return PathShape::Lawnmower;
  throw std::invalid_argument("unknown path '" + name + "' (expected one of: loop, lawnmower)");
}

SimTrajectory generatePath(const PathOptions& options, std::mt19937& rng) {
  check(options.dimension == 2 || options.dimension == 3, "the dimension must be 2 or 3");
  check(options.steps >= 1, "steps must be >= 1");
  check(std::isfinite(options.stepLength) && options.stepLength > 0.0, "the step length must be positive");
  check(options.loops >= 1, "loops must be >= 1");
  check(std::isfinite(options.rowLength) && options.rowLength > 0.0, "the row length must be positive");
  check(std::isfinite(options.rowSpacing) && options.rowSpacing > 0.0, "the row spacing must be positive");
  check(std::isfinite(options.heightAmplitude) && options.heightAmplitude >= 0.0, "the height amplitude must be >= 0");
  check(std::isfinite(options.timeStep) && options.timeStep > 0.0, "the time step must be positive");

  std::vector<PathPoint> points;
  if (options.shape == PathShape::Loop) {
    points = sampleLoop(options, rng);
  } else {
    for (int k = 0; k <= options.steps; ++k) points.push_back(lawnmowerPoint(options, k * options.stepLength));
  }
  SimTrajectory trajectory;
  // Move the first pose to the origin, heading +x, keeping z up (a 3D path may start on a slope).
  const Vector3& t0 = points.front().tangent;
  const SE3 firstInverse =
      SE3(SO3::fromAxisAngle(Vector3::UnitZ(), std::atan2(t0.y(), t0.x())), points.front().position).inverse();
  for (int k = 0; k <= options.steps; ++k) {
    trajectory.times.push_back(k * options.timeStep);
    const SE3 pose = firstInverse.compose(poseFromPathPoint(points[k]));
    if (options.dimension == 3) {
      trajectory.poses.emplace_back(pose);
    } else {
      const Matrix3& R = pose.rotation().matrix();
      trajectory.poses.emplace_back(SE2(pose.translation().x(), pose.translation().y(), std::atan2(R(1, 0), R(0, 0))));
    }
  }
  return trajectory;
}

}  // namespace semslam
