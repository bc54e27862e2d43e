#include "semslam/eval/Nees.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <string>

#include "semslam/core/ChiSquare.h"
#include "semslam/eval/ErrorStatistics.h"
#include "semslam/core/InputError.h"

namespace semslam {

double normalizedErrorSquared(const Vector& error, const Matrix& covariance) {
  if (covariance.rows() != error.size() || covariance.cols() != error.size()) {
    throw InputError("NEES: the covariance is " + std::to_string(covariance.rows()) + "x" +
                     std::to_string(covariance.cols()) + " for an error of dimension " + std::to_string(error.size()));
  }
  if (!error.allFinite() || !covariance.allFinite()) throw InputError("NEES: non-finite error or covariance");
  const double scale = std::max(1e-300, covariance.cwiseAbs().maxCoeff());
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    throw InputError("NEES: the covariance is not symmetric");
  }
  const Eigen::LLT<Matrix> cholesky(covariance);
  if (cholesky.info() != Eigen::Success) throw InputError("NEES: the covariance is not positive definite");
  const Vector whitened = cholesky.matrixL().solve(error);  // L⁻¹ e, so that eᵀ Σ⁻¹ e = ‖L⁻¹ e‖²
  return whitened.squaredNorm();
}

Vector3 poseError(const SE2& estimate, const SE2& truth) { return SE2::Log(estimate.between(truth)); }

Vector6 poseError(const SE3& estimate, const SE3& truth) { return SE3::Log(estimate.between(truth)); }

double poseNees(const SE2& estimate, const SE2& truth, const Matrix& covariance) {
  return normalizedErrorSquared(poseError(estimate, truth), covariance);
}

double poseNees(const SE3& estimate, const SE3& truth, const Matrix& covariance) {
  return normalizedErrorSquared(poseError(estimate, truth), covariance);
}

double pointNees(const Vector& estimate, const Vector& truth, const Matrix& covariance) {
  if (estimate.size() != truth.size()) throw InputError("NEES: the point estimate and the truth differ in size");
  return normalizedErrorSquared(truth - estimate, covariance);
}

NeesSummary summarizeNees(const std::vector<double>& values, int dimension, double confidence) {
  if (dimension < 1) throw InputError("NEES summary: the dimension must be >= 1");
  if (!(confidence > 0.0 && confidence < 1.0)) throw InputError("NEES summary: the confidence must be in (0, 1)");
  NeesSummary summary;
  summary.count = values.size();
  summary.dimension = dimension;
  summary.confidence = confidence;
  if (values.empty()) return summary;
  for (double v : values) {
    if (!(v >= 0.0) || !std::isfinite(v)) throw InputError("NEES summary: a value is negative or not finite");
  }
  const double n = static_cast<double>(values.size());
  summary.mean = pairwiseSum(values.data(), values.size()) / n;
  const double dof = n * dimension;
  const double alpha = 1.0 - confidence;
  summary.lower = chiSquareQuantile(0.5 * alpha, dof) / n;
  summary.upper = chiSquareQuantile(1.0 - 0.5 * alpha, dof) / n;
  return summary;
}

}  // namespace semslam
