#include "semslam/geometry/SE3.h"

#include <array>
#include <cmath>
#include <ostream>

namespace semslam {

namespace {

// Below this angle c1, c2, c3 come from their Taylor series (10 terms: truncation < 1e-19 relative); above it the
// closed forms lose at most ~1e-13 relative to cancellation (and their products with powers of φ^ far less).
constexpr double kQSeriesAngle = 1.0;

struct QCoefficients {
  double c1, c2, c3;
};

// Taylor coefficients (in x = -θ²) of
//   c1 = (θ - sin θ)/θ³               = Σ_j (-θ²)^j / (2j+3)!
//   c2 = (θ² + 2cos θ - 2)/(2θ⁴)      = Σ_j (-θ²)^j / (2j+4)!
//   c3 = (2θ - 3sin θ + θcos θ)/(2θ⁵) = Σ_j (-θ²)^j (j+1) / (2j+5)!
constexpr int kQSeriesTerms = 10;
struct QSeries {
  std::array<double, kQSeriesTerms> c1{}, c2{}, c3{};
};
constexpr QSeries makeQSeries() {
  QSeries series;
  double invFactorial = 1.0 / 6.0;  // 1/(2j+3)!
  for (int j = 0; j < kQSeriesTerms; ++j) {
    const double n = 2.0 * j + 3.0;
    series.c1[j] = invFactorial;
    series.c2[j] = invFactorial / (n + 1.0);
    series.c3[j] = (j + 1.0) * invFactorial / ((n + 1.0) * (n + 2.0));
    invFactorial /= (n + 1.0) * (n + 2.0);
  }
  return series;
}
constexpr QSeries kQSeries = makeQSeries();

double horner(const std::array<double, kQSeriesTerms>& coefficients, double x) {
  double sum = coefficients[kQSeriesTerms - 1];
  for (int j = kQSeriesTerms - 2; j >= 0; --j) sum = coefficients[j] + x * sum;
  return sum;
}

QCoefficients qCoefficients(double theta) {
  const double t2 = theta * theta;
  if (theta < kQSeriesAngle) {
    return {horner(kQSeries.c1, -t2), horner(kQSeries.c2, -t2), horner(kQSeries.c3, -t2)};
  }
  const double s = std::sin(theta), c = std::cos(theta);
  const double t3 = t2 * theta;
  return {(theta - s) / t3, (t2 + 2.0 * c - 2.0) / (2.0 * t2 * t2),
          (2.0 * theta - 3.0 * s + theta * c) / (2.0 * t3 * t2)};
}

// Barfoot's Q(ρ, φ), the top-right block of the left Jacobian of SE(3) (translation first).
Matrix3 leftJacobianQ(const Vector3& rho, const Vector3& phi) {
  const QCoefficients k = qCoefficients(phi.norm());
  const Matrix3 P = SO3::hat(rho);
  const Matrix3 W = SO3::hat(phi);
  const Matrix3 WP = W * P;
  const Matrix3 PW = P * W;
  const Matrix3 WPW = WP * W;
  return 0.5 * P + k.c1 * (WP + PW + WPW) + k.c2 * (W * WP + PW * W - 3.0 * WPW) + k.c3 * (WPW * W + W * WPW);
}

Matrix6 blockUpperTriangular(const Matrix3& diagonal, const Matrix3& offDiagonal) {
  Matrix6 M;
  M.topLeftCorner<3, 3>() = diagonal;
  M.topRightCorner<3, 3>() = offDiagonal;
  M.bottomLeftCorner<3, 3>().setZero();
  M.bottomRightCorner<3, 3>() = diagonal;
  return M;
}

}  // namespace

SE3 SE3::Exp(const Vector6& xi, Matrix6* H) {
  const Vector3 rho = xi.head<3>();
  const Vector3 phi = xi.tail<3>();
  Matrix3 J;  // Jr(φ); V(φ) = Jl(φ) = Jr(φ)ᵀ
  const SO3 R = SO3::Exp(phi, &J);
  if (H) *H = blockUpperTriangular(J, leftJacobianQ(-rho, -phi));
  return SE3(R, J.transpose() * rho);
}

Vector6 SE3::Log(const SE3& T, Matrix6* H) {
  Matrix3 Jinv;  // Jr(φ)⁻¹; V(φ)⁻¹ = Jl(φ)⁻¹ = Jr(φ)⁻ᵀ
  const Vector3 phi = SO3::Log(T.R_, &Jinv);
  const Vector3 rho = Jinv.transpose() * T.t_;
  if (H) *H = blockUpperTriangular(Jinv, -Jinv * leftJacobianQ(-rho, -phi) * Jinv);
  Vector6 xi;
  xi << rho, phi;
  return xi;
}

Matrix6 SE3::rightJacobian(const Vector6& xi) {
  const Vector3 rho = xi.head<3>();
  const Vector3 phi = xi.tail<3>();
  return blockUpperTriangular(SO3::rightJacobian(phi), leftJacobianQ(-rho, -phi));
}

Matrix6 SE3::rightJacobianInverse(const Vector6& xi) {
  const Vector3 rho = xi.head<3>();
  const Vector3 phi = xi.tail<3>();
  const Matrix3 Jinv = SO3::rightJacobianInverse(phi);
  return blockUpperTriangular(Jinv, -Jinv * leftJacobianQ(-rho, -phi) * Jinv);
}

std::ostream& operator<<(std::ostream& os, const SE3& T) {
  const Point3& t = T.translation();
  const Vector3 w = SO3::Log(T.rotation());
  return os << "SE3(t: " << t.x() << " " << t.y() << " " << t.z() << ", R: " << w.x() << " " << w.y() << " "
            << w.z() << ")";
}

}  // namespace semslam
