#pragma once
// Fixed- and dynamic-size matrix names used throughout semslam (all double precision, column-major Eigen).

#include <Eigen/Core>

namespace semslam {

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

template <int Rows>
using VectorN = Eigen::Matrix<double, Rows, 1>;
template <int Rows, int Cols>
using MatrixN = Eigen::Matrix<double, Rows, Cols>;

using Vector1 = VectorN<1>;
using Vector2 = VectorN<2>;
using Vector3 = VectorN<3>;
using Vector4 = VectorN<4>;
using Vector6 = VectorN<6>;
using Matrix1 = MatrixN<1, 1>;
using Matrix2 = MatrixN<2, 2>;
using Matrix3 = MatrixN<3, 3>;
using Matrix4 = MatrixN<4, 4>;
using Matrix6 = MatrixN<6, 6>;
using Matrix23 = MatrixN<2, 3>;
using Matrix32 = MatrixN<3, 2>;
using Matrix36 = MatrixN<3, 6>;
using Matrix63 = MatrixN<6, 3>;

/// Points are plain Eigen vectors.
using Point2 = Vector2;
using Point3 = Vector3;

}  // namespace semslam
