#include "semslam/graph/NoiseModel.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace semslam {

namespace {

void requireFiniteSquare(const Matrix& m, const char* what) {
  if (m.rows() == 0 || m.rows() != m.cols()) {
    throw std::invalid_argument(std::string(what) + " must be square and non-empty, got " + std::to_string(m.rows()) +
                                "x" + std::to_string(m.cols()));
  }
  if (!m.allFinite()) throw std::invalid_argument(std::string(what) + " has a NaN or infinite entry");
}

void requireSymmetric(const Matrix& m, const char* what) {
  const double scale = std::max(1.0, m.cwiseAbs().maxCoeff());
  if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    throw std::invalid_argument(std::string(what) + " is not symmetric");
  }
}

/// Upper-triangular U with UᵀU = A, for symmetric positive definite A.
Matrix upperCholesky(const Matrix& a, const char* what) {
  Eigen::LLT<Matrix> llt(a);
  if (llt.info() != Eigen::Success) throw std::invalid_argument(std::string(what) + " is not positive definite");
  Matrix upper = llt.matrixU();
  if (!(upper.diagonal().array() > 0.0).all() || !upper.allFinite()) {
    throw std::invalid_argument(std::string(what) + " is not positive definite");
  }
  return upper;
}

bool isDiagonalMatrix(const Matrix& m) {
  return (m - Matrix(m.diagonal().asDiagonal())).cwiseAbs().maxCoeff() == 0.0;
}

}  // namespace

NoiseModel::NoiseModel(Matrix sqrtInformation, bool diagonal)
    : sqrtInformation_(std::move(sqrtInformation)), diagonal_(diagonal) {
  const int d = dimension();
  logNormalizer_ = 0.5 * d * std::log(2.0 * std::numbers::pi) -
                   sqrtInformation_.diagonal().array().log().sum();
}

SharedNoiseModel NoiseModel::fromCovariance(const Matrix& covariance) {
  requireFiniteSquare(covariance, "covariance");
  requireSymmetric(covariance, "covariance");
  // Σ = LLᵀ  ⇒  Σ⁻¹ = L⁻ᵀL⁻¹, and R = chol(Σ⁻¹) is computed from the information for an upper-triangular R.
  const Matrix symmetric = 0.5 * (covariance + covariance.transpose());
  upperCholesky(symmetric, "covariance");  // rejects a covariance that is not positive definite
  const Matrix information = symmetric.inverse();
  return SharedNoiseModel(
      new NoiseModel(upperCholesky(0.5 * (information + information.transpose()), "covariance"),
                     isDiagonalMatrix(covariance)));
}

SharedNoiseModel NoiseModel::fromInformation(const Matrix& information) {
  requireFiniteSquare(information, "information matrix");
  requireSymmetric(information, "information matrix");
  const Matrix symmetric = 0.5 * (information + information.transpose());
  return SharedNoiseModel(
      new NoiseModel(upperCholesky(symmetric, "information matrix"), isDiagonalMatrix(information)));
}

SharedNoiseModel NoiseModel::fromSqrtInformation(const Matrix& sqrtInformation) {
  requireFiniteSquare(sqrtInformation, "square-root information matrix");
  const Matrix lower = sqrtInformation.triangularView<Eigen::StrictlyLower>();
  if (lower.cwiseAbs().maxCoeff() > 0.0) {
    throw std::invalid_argument("square-root information matrix is not upper triangular");
  }
  // R and R with rows negated describe the same Gaussian; normalise to a positive diagonal.
  Matrix r = sqrtInformation;
  for (int i = 0; i < r.rows(); ++i) {
    if (r(i, i) == 0.0) throw std::invalid_argument("square-root information matrix is singular");
    if (r(i, i) < 0.0) r.row(i) *= -1.0;
  }
  return SharedNoiseModel(new NoiseModel(r, isDiagonalMatrix(r)));
}

SharedNoiseModel NoiseModel::fromSigmas(const Vector& sigmas) {
  if (sigmas.size() == 0) throw std::invalid_argument("sigmas must not be empty");
  if (!sigmas.allFinite() || !(sigmas.array() > 0.0).all()) {
    throw std::invalid_argument("sigmas must be finite and > 0");
  }
  return SharedNoiseModel(new NoiseModel(Matrix(sigmas.cwiseInverse().asDiagonal()), true));
}

SharedNoiseModel NoiseModel::isotropic(int dimension, double sigma) {
  if (dimension <= 0) throw std::invalid_argument("dimension must be > 0");
  return fromSigmas(Vector::Constant(dimension, sigma));
}

SharedNoiseModel NoiseModel::withRobustKernel(SharedRobustKernel kernel) const {
  auto copy = std::shared_ptr<NoiseModel>(new NoiseModel(*this));
  copy->kernel_ = std::move(kernel);
  return copy;
}

double NoiseModel::largestWhitenedNormInBox(const Vector& halfWidths) const {
  if (halfWidths.size() != dimension()) throw std::invalid_argument("box of the wrong dimension for the noise model");
  double largest = 0.0;
  Vector corner(dimension());
  for (unsigned signs = 0; signs < (1u << dimension()); ++signs) {
    for (int i = 0; i < dimension(); ++i) corner(i) = (signs >> i) & 1u ? -halfWidths(i) : halfWidths(i);
    whitenInPlace(corner);
    largest = std::max(largest, corner.squaredNorm());
  }
  return std::sqrt(largest);
}

double NoiseModel::largestErrorEntry(int i, double chi2) const {
  const Vector unit = Vector::Unit(dimension(), i);
  const Vector row = sqrtInformation_.triangularView<Eigen::Upper>().transpose().solve(unit);  // (row i of R⁻¹)ᵀ
  return std::sqrt(chi2) * row.norm();
}

Matrix NoiseModel::covariance() const {
  const Matrix rInverse = sqrtInformation_.triangularView<Eigen::Upper>().solve(
      Matrix::Identity(dimension(), dimension()));
  return rInverse * rInverse.transpose();
}

}  // namespace semslam
