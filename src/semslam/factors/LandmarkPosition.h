#pragma once
// The position of a landmark variable: a point is its own position; an object with a pose (paper A's objects
// have an orientation) has the translation of its pose. With the Jacobian of that position with respect to the
// landmark's right perturbation: I for points, [R 0] for poses (o · Exp(δ) moves the origin by R δ_t).

#include <type_traits>

#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"

namespace semslam {

template <class Landmark>
struct LandmarkPosition;

template <>
struct LandmarkPosition<Point2> {
  using Point = Point2;
  static Point2 of(const Point2& l, MatrixN<2, 2>* H) {
    if (H) H->setIdentity();
    return l;
  }
};

template <>
struct LandmarkPosition<Point3> {
  using Point = Point3;
  static Point3 of(const Point3& l, MatrixN<3, 3>* H) {
    if (H) H->setIdentity();
    return l;
  }
};

template <>
struct LandmarkPosition<SE2> {
  using Point = Point2;
  static Point2 of(const SE2& o, MatrixN<2, 3>* H) { return o.transformFrom(Point2::Zero(), H, nullptr); }
};

template <>
struct LandmarkPosition<SE3> {
  using Point = Point3;
  static Point3 of(const SE3& o, MatrixN<3, 6>* H) { return o.transformFrom(Point3::Zero(), H, nullptr); }
};

}  // namespace semslam
