#pragma once
// Ambient coordinates of a semslam value for Ceres: a flat array of exactly the value's tangent dimension that
// holds the whole value (Ceres evaluates cost functions at its own candidate states, through pointers into its
// own arrays, so the array must be the value, not a handle to one).
//
//   Point2, Point3   the point itself
//   SO2              θ
//   SE2              (x, y, θ)
//   SO3              the rotation vector φ = Log(R), |φ| ≤ π
//   SE3              (t, φ): translation, then the rotation vector of R
//
// These are charts of the same dimension as the tangent space, which is what lets ValueManifold report an
// identity PlusJacobian (see there).

#include <cstddef>

#include "semslam/graph/Values.h"

namespace semslam::bench {

/// Which alternative of semslam::Value a variable is (its std::variant index).
using ValueKind = std::size_t;

inline ValueKind kindOf(const Value& value) { return value.index(); }

/// Number of ambient coordinates (= tangent dimension) of a value of kind `kind`.
int ambientSize(ValueKind kind);

/// Writes `value` as dimension(value) doubles.
void toAmbient(const Value& value, double* ambient);

/// The value of kind `kind` whose ambient coordinates are `ambient`.
Value fromAmbient(ValueKind kind, const double* ambient);

}  // namespace semslam::bench
