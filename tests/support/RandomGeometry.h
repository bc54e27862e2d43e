#pragma once
// Seeded random inputs for the Lie group tests. Each draw consumes the engine in a fixed order, so a test's inputs
// depend only on its seed:
//   RandomPlane   uniform(lo, hi); angle() uniform in [−π, π); point() uniform in [−5, 5]², x drawn first;
//   RandomSpace   uniform(lo, hi); gaussian3() ~ N(0, I₃); axis() a uniformly distributed unit vector (a
//                 normalised gaussian3()); point() uniform in [−5, 5]³; rotation() Haar-uniform, from a normalised
//                 Gaussian quaternion (w, x, y, z drawn in that order).

#include <numbers>
#include <random>

#include <Eigen/Geometry>

#include "semslam/geometry/SO2.h"
#include "semslam/geometry/SO3.h"

namespace semslam::test {

struct RandomPlane {
  explicit RandomPlane(unsigned seed) : rng(seed) {}
  std::mt19937 rng;
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  double angle() { return uniform(-std::numbers::pi, std::numbers::pi); }
  Point2 point() {
    const double x = uniform(-5.0, 5.0);
    return Point2(x, uniform(-5.0, 5.0));
  }
};

struct RandomSpace {
  explicit RandomSpace(unsigned seed) : rng(seed) {}
  std::mt19937 rng;
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vector3 gaussian3() {
    std::normal_distribution<double> n(0.0, 1.0);
    const double x = n(rng), y = n(rng);
    return Vector3(x, y, n(rng));
  }
  Vector3 axis() { return gaussian3().normalized(); }
  Point3 point() {
    const double x = uniform(-5.0, 5.0), y = uniform(-5.0, 5.0);
    return Point3(x, y, uniform(-5.0, 5.0));
  }
  SO3 rotation() {
    std::normal_distribution<double> n(0.0, 1.0);
    const double w = n(rng), x = n(rng), y = n(rng);
    return SO3::fromQuaternion(Eigen::Quaterniond(w, x, y, n(rng)));
  }
};

}  // namespace semslam::test
