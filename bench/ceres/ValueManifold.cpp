#include "ValueManifold.h"

#include <algorithm>

namespace semslam::bench {

namespace {

void writeIdentity(int size, double* matrix) {
  std::fill(matrix, matrix + size * size, 0.0);
  for (int i = 0; i < size; ++i) matrix[i * size + i] = 1.0;
}

}  // namespace

ValueManifold::ValueManifold(ValueKind kind) : kind_(kind), size_(ambientSize(kind)) {}

bool ValueManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  const Value moved = retract(fromAmbient(kind_, x), Eigen::Map<const Vector>(delta, size_));
  toAmbient(moved, x_plus_delta);
  return true;
}

bool ValueManifold::PlusJacobian(const double* /*x*/, double* jacobian) const {
  writeIdentity(size_, jacobian);
  return true;
}

bool ValueManifold::RightMultiplyByPlusJacobian(const double* /*x*/, int num_rows, const double* ambient_matrix,
                                                double* tangent_matrix) const {
  std::copy(ambient_matrix, ambient_matrix + num_rows * size_, tangent_matrix);
  return true;
}

bool ValueManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  const Value from = fromAmbient(kind_, x);
  const Value to = fromAmbient(kind_, y);
  std::visit(
      [&to, y_minus_x, this](const auto& a) {
        using T = std::decay_t<decltype(a)>;
        Eigen::Map<Vector>(y_minus_x, size_) = semslam::Manifold<T>::local(a, std::get<T>(to));
      },
      from);
  return true;
}

bool ValueManifold::MinusJacobian(const double* /*x*/, double* jacobian) const {
  writeIdentity(size_, jacobian);
  return true;
}

}  // namespace semslam::bench
