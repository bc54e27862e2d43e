#include "FactorCostFunction.h"

#include <exception>
#include <stdexcept>

namespace semslam::bench {

FactorCostFunction::FactorCostFunction(FactorPtr factor, std::vector<ValueKind> kinds)
    : factor_(std::move(factor)), kinds_(std::move(kinds)) {
  if (kinds_.size() != factor_->keys().size()) {
    throw std::invalid_argument("FactorCostFunction: one value kind per key is needed");
  }
  set_num_residuals(factor_->errorDimension());
  for (ValueKind kind : kinds_) {
    mutable_parameter_block_sizes()->push_back(ambientSize(kind));
  }
}

bool FactorCostFunction::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  Values view;
  thread_local LinearizedFactor linearized;  // its buffers are sized once per thread
  const std::vector<Key>& keys = factor_->keys();
  try {
    for (std::size_t k = 0; k < keys.size(); ++k) view.insertOrAssign(keys[k], fromAmbient(kinds_[k], parameters[k]));
    factor_->linearize(view, linearized);
  } catch (const std::exception&) {
    return false;  // Ceres treats a failed evaluation as a rejected step
  }
  const int rows = num_residuals();
  Eigen::Map<Vector>(residuals, rows) = linearized.whitenedError;
  if (jacobians != nullptr) {
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (jacobians[k] == nullptr) continue;  // a constant parameter block
      const Matrix& jacobian = linearized.jacobians[k];
      Eigen::Map<RowMajor>(jacobians[k], rows, jacobian.cols()) = jacobian;
    }
  }
  return true;
}

}  // namespace semslam::bench
