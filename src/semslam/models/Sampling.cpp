#include "semslam/models/Sampling.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>

namespace semslam {

double uniform01(std::mt19937& rng) {
  const std::uint64_t a = rng();       // 32 bits
  const std::uint64_t b = rng() >> 11;  // 21 bits
  return static_cast<double>((a << 21) | b) * 0x1.0p-53;
}

double standardNormal(std::mt19937& rng) {
  const double u1 = uniform01(rng);
  const double u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Matrix standardNormalMatrix(Eigen::Index rows, Eigen::Index cols, std::mt19937& rng) {
  if (rows < 0 || cols < 0) throw std::invalid_argument("standardNormalMatrix: negative size");
  Matrix draws(rows, cols);
  double* entry = draws.data();
  const Eigen::Index count = draws.size();
  for (Eigen::Index i = 0; i < count; i += 2) {
    const double u1 = uniform01(rng);
    const double u2 = uniform01(rng);
    const double radius = std::sqrt(-2.0 * std::log(1.0 - u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    entry[i] = radius * std::cos(angle);
    if (i + 1 < count) entry[i + 1] = radius * std::sin(angle);
  }
  return draws;
}

Matrix gaussianSquareRoot(const Matrix& covariance) {
  const Eigen::Index d = covariance.rows();
  if (covariance.cols() != d) {
    throw std::invalid_argument("gaussianSquareRoot: covariance is " + std::to_string(covariance.rows()) + "x" +
                                std::to_string(covariance.cols()));
  }
  if (!covariance.allFinite()) throw std::invalid_argument("gaussianSquareRoot: NaN or infinite covariance entry");
  const double scale = d == 0 ? 0.0 : covariance.cwiseAbs().maxCoeff();
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, scale)) {
    throw std::invalid_argument("gaussianSquareRoot: covariance is not symmetric");
  }
  const Matrix symmetric = 0.5 * (covariance + covariance.transpose());
  Eigen::LLT<Matrix> llt(symmetric);
  if (llt.info() == Eigen::Success) return llt.matrixL();
  Eigen::SelfAdjointEigenSolver<Matrix> eigen(symmetric);
  if (eigen.info() != Eigen::Success || eigen.eigenvalues().minCoeff() < -1e-12 * std::max(1.0, scale)) {
    throw std::invalid_argument("gaussianSquareRoot: covariance is not positive semi-definite");
  }
  return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

Vector sampleGaussian(const Vector& mean, const Matrix& covariance, std::mt19937& rng) {
  const Eigen::Index d = mean.size();
  if (covariance.rows() != d || covariance.cols() != d) {
    throw std::invalid_argument("sampleGaussian: covariance is " + std::to_string(covariance.rows()) + "x" +
                                std::to_string(covariance.cols()) + ", the mean has " + std::to_string(d) +
                                " entries");
  }
  if (!mean.allFinite()) throw std::invalid_argument("sampleGaussian: NaN or infinite entry in the mean");
  Vector n(d);
  for (Eigen::Index i = 0; i < d; ++i) n(i) = standardNormal(rng);
  return mean + gaussianSquareRoot(covariance) * n;
}

}  // namespace semslam
