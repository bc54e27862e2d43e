#include "semslam/models/OdometryComposition.h"

#include <stdexcept>
#include <string>

namespace semslam {

namespace {

template <class Group>
Odometry composeTyped(const Group& a, const Matrix& covarianceA, const Group& b, const Matrix& covarianceB) {
  using Jacobian = Eigen::Matrix<double, Group::kDim, Group::kDim>;
  Jacobian Ha;  // Ad(b⁻¹)
  Odometry result;
  result.increment = a.compose(b, &Ha, nullptr);
  const Matrix covariance = Ha * covarianceA * Ha.transpose() + covarianceB;
  result.covariance = 0.5 * (covariance + covariance.transpose());
  return result;
}

}  // namespace

void checkOdometry(const Odometry& odometry) {
  const int d = std::holds_alternative<SE2>(odometry.increment) ? 3 : 6;
  const Matrix& c = odometry.covariance;
  if (c.rows() != d || c.cols() != d) {
    throw std::invalid_argument(std::string("odometry: a ") + (d == 3 ? "SE2" : "SE3") + " increment needs a " +
                                std::to_string(d) + "x" + std::to_string(d) + " covariance, got " +
                                std::to_string(c.rows()) + "x" + std::to_string(c.cols()));
  }
  if (!c.allFinite()) throw std::invalid_argument("odometry: the covariance has a NaN or infinite entry");
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, c.cwiseAbs().maxCoeff())) {
    throw std::invalid_argument("odometry: the covariance is not symmetric");
  }
}

Odometry identityOdometry(int dimension) {
  Odometry o;
  if (dimension == 2) {
    o.increment = SE2();
    o.covariance = Matrix::Zero(3, 3);
  } else if (dimension == 3) {
    o.increment = SE3();
    o.covariance = Matrix::Zero(6, 6);
  } else {
    throw std::invalid_argument("identityOdometry: dimension must be 2 or 3, got " + std::to_string(dimension));
  }
  return o;
}

Odometry composeOdometry(const Odometry& first, const Odometry& second) {
  checkOdometry(first);
  checkOdometry(second);
  if (first.increment.index() != second.increment.index()) {
    throw std::invalid_argument("composeOdometry: cannot compose an SE2 increment with an SE3 increment");
  }
  if (const auto* a = std::get_if<SE2>(&first.increment)) {
    return composeTyped(*a, first.covariance, std::get<SE2>(second.increment), second.covariance);
  }
  return composeTyped(std::get<SE3>(first.increment), first.covariance, std::get<SE3>(second.increment),
                      second.covariance);
}

}  // namespace semslam
