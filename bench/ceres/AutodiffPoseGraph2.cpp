#include "AutodiffPoseGraph2.h"

#include <ceres/autodiff_cost_function.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"

namespace semslam::bench {

namespace {

/// a⁻¹ · b for poses given as (x, y, θ).
template <class T, class U>
void between(const T* a, const U* b, T* out) {
  using std::cos;
  using std::sin;
  const T c = cos(a[2]);
  const T s = sin(a[2]);
  const T dx = b[0] - a[0];
  const T dy = b[1] - a[1];
  out[0] = c * dx + s * dy;
  out[1] = -s * dx + c * dy;
  out[2] = b[2] - a[2];
}

/// Whitened Log(z⁻¹ · pose): θ wrapped to (-π, π], ρ = V(θ)⁻¹ t with V⁻¹ = [α θ/2; -θ/2 α], α = (θ/2) cot(θ/2).
template <class T>
void whitenedLogFrom(const double* z, const T* pose, const Matrix3& sqrtInformation, T* residual) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  const T measured[3] = {T(z[0]), T(z[1]), T(z[2])};
  T e[3];
  between(measured, pose, e);
  const T theta = atan2(sin(e[2]), cos(e[2]));
  const T half = 0.5 * theta;
  const T alpha = abs(theta) < 1e-6 ? T(1.0) - theta * theta / 12.0 : half * cos(half) / sin(half);
  const T log[3] = {alpha * e[0] + half * e[1], -half * e[0] + alpha * e[1], theta};
  for (int i = 0; i < 3; ++i) {
    residual[i] = T(0.0);
    for (int j = 0; j < 3; ++j) residual[i] += sqrtInformation(i, j) * log[j];
  }
}

struct BetweenResidual {
  double z[3];
  Matrix3 sqrtInformation;
  template <class T>
  bool operator()(const T* xi, const T* xj, T* residual) const {
    T relative[3];
    between(xi, xj, relative);
    whitenedLogFrom(z, relative, sqrtInformation, residual);
    return true;
  }
};

struct PriorResidual {
  double z[3];
  Matrix3 sqrtInformation;
  template <class T>
  bool operator()(const T* x, T* residual) const {
    whitenedLogFrom(z, x, sqrtInformation, residual);
    return true;
  }
};

}  // namespace

AutodiffPoseGraph2::AutodiffPoseGraph2(const FactorGraph& graph, const Values& initial) {
  keys_ = graph.keys();
  poses_.resize(3 * keys_.size());
  for (std::size_t v = 0; v < keys_.size(); ++v) {
    if (!initial.exists(keys_[v]) || !std::holds_alternative<SE2>(initial.value(keys_[v]))) {
      throw std::invalid_argument("the autodiff SE2 benchmark needs an SE2 value for " + keyToString(keys_[v]));
    }
    const SE2& pose = initial.at<SE2>(keys_[v]);
    poses_[3 * v] = pose.x();
    poses_[3 * v + 1] = pose.y();
    poses_[3 * v + 2] = pose.theta();
  }
  const auto block = [this](Key key) {
    return &poses_[3 * static_cast<std::size_t>(std::lower_bound(keys_.begin(), keys_.end(), key) - keys_.begin())];
  };
  const auto measurement = [](const SE2& z, double* out) {
    out[0] = z.x();
    out[1] = z.y();
    out[2] = z.theta();
  };

  problem_ = std::make_unique<ceres::Problem>();
  for (const FactorPtr& factor : graph) {
    const auto* edge = dynamic_cast<const BetweenFactor<SE2>*>(factor.get());
    const auto* prior = dynamic_cast<const PriorFactor<SE2>*>(factor.get());
    if ((edge && edge->noiseModel()->robustKernel()) || (prior && prior->noiseModel()->robustKernel())) {
      throw std::invalid_argument("the autodiff SE2 benchmark has no robust kernels");
    }
    if (edge) {
      auto* residual = new BetweenResidual;
      measurement(edge->measured(), residual->z);
      residual->sqrtInformation = edge->noiseModel()->sqrtInformation();
      problem_->AddResidualBlock(new ceres::AutoDiffCostFunction<BetweenResidual, 3, 3, 3>(residual), nullptr,
                                 block(edge->keys()[0]), block(edge->keys()[1]));
    } else if (prior) {
      auto* residual = new PriorResidual;
      measurement(prior->prior(), residual->z);
      residual->sqrtInformation = prior->noiseModel()->sqrtInformation();
      problem_->AddResidualBlock(new ceres::AutoDiffCostFunction<PriorResidual, 3, 3>(residual), nullptr,
                                 block(prior->keys()[0]));
    } else {
      throw std::invalid_argument("the autodiff SE2 benchmark handles SE2 between and prior factors only");
    }
  }
}

ceres::Solver::Summary AutodiffPoseGraph2::solve(const ceres::Solver::Options& options) {
  ceres::Solver::Summary summary;
  ceres::Solve(options, problem_.get(), &summary);
  return summary;
}

Values AutodiffPoseGraph2::values() const {
  Values result;
  for (std::size_t v = 0; v < keys_.size(); ++v) {
    result.insert(keys_[v], SE2(poses_[3 * v], poses_[3 * v + 1], poses_[3 * v + 2]));
  }
  return result;
}

}  // namespace semslam::bench
