#include "semslam/eval/PoseMixtureMoments.h"

#include <cmath>
#include <stdexcept>

namespace semslam {
namespace {

constexpr int kMaxIterations = 100;
constexpr double kTolerance = 1e-10;

}  // namespace

PoseGaussian2 momentMatchedPoseMixture(const std::vector<double>& weights, const std::vector<SE2>& means,
                                       const std::vector<Matrix3>& covariances) {
  if (weights.empty() || weights.size() != means.size() || weights.size() != covariances.size()) {
    throw std::invalid_argument("mixture moments: weights, means and covariances must be non-empty and of one size");
  }
  double total = 0.0;
  std::size_t heaviest = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!(weights[i] >= 0.0) || !std::isfinite(weights[i])) {
      throw std::invalid_argument("mixture moments: weights must be finite and >= 0");
    }
    total += weights[i];
    if (weights[i] > weights[heaviest]) heaviest = i;
  }
  if (!(total > 0.0)) throw std::invalid_argument("mixture moments: every weight is zero");

  // The weighted Karcher mean, from the heaviest component's mean.
  SE2 mean = means[heaviest];
  std::vector<Vector3> deltas(means.size());
  for (int iteration = 0;; ++iteration) {
    Vector3 step = Vector3::Zero();
    for (std::size_t i = 0; i < means.size(); ++i) {
      deltas[i] = SE2::Log(mean.between(means[i]));
      step += (weights[i] / total) * deltas[i];
    }
    if (step.norm() <= kTolerance) break;
    if (iteration == kMaxIterations) {
      throw std::invalid_argument("mixture moments: the mean did not converge (components more than a half turn apart?)");
    }
    mean = mean.compose(SE2::Exp(step));
  }
  Matrix3 covariance = Matrix3::Zero();
  for (std::size_t i = 0; i < means.size(); ++i) {
    const Matrix3 transport = SE2::rightJacobianInverse(deltas[i]);  // e at μ_i → m's tangent, first order
    covariance += (weights[i] / total) * (transport * covariances[i] * transport.transpose() +
                                          deltas[i] * deltas[i].transpose());
  }
  return {mean, 0.5 * (covariance + covariance.transpose())};
}

}  // namespace semslam
