#pragma once
// The linear-Gaussian toy of the marginal-likelihood tests: two correlated points, each measured directly, so that
//     p(z) = N([za; zb]; [ā; b̄], Σ + blockdiag(Ra, Rb))   in closed form.

#include <memory>
#include <vector>

#include "semslam/factors/PriorFactor.h"
#include "semslam/graph/NoiseModel.h"
#include "semslam/solve/JointMarginal.h"
#include "support/GaussianDensity.h"

namespace semslam::test {

struct LinearToy {
  Key a = landmarkKey(0), b = landmarkKey(1);
  Values values;
  Matrix covariance = Matrix(4, 4);
  Vector2 za = Vector2(1.3, -0.4), zb = Vector2(2.2, 0.9);
  Matrix Ra = Vector2(0.3, 0.2).asDiagonal(), Rb = (Matrix(2, 2) << 0.5, 0.1, 0.1, 0.4).finished();
  std::vector<FactorPtr> factors;
  JointMarginal marginal;

  LinearToy() {
    values.insert(a, Point2(1.0, -0.5));
    values.insert(b, Point2(2.0, 1.2));
    covariance << 0.20, 0.05, 0.08, 0.00,  //
        0.05, 0.30, 0.02, 0.06,            //
        0.08, 0.02, 0.25, -0.04,           //
        0.00, 0.06, -0.04, 0.15;
    measure(za, zb);
    marginal = JointMarginal({a, b}, {2, 2}, covariance);
  }

  /// Sets the measurements and rebuilds the factors.
  void measure(const Vector2& measuredA, const Vector2& measuredB) {
    za = measuredA;
    zb = measuredB;
    factors = {std::make_shared<const PriorFactor<Point2>>(a, za, NoiseModel::fromCovariance(Ra)),
               std::make_shared<const PriorFactor<Point2>>(b, zb, NoiseModel::fromCovariance(Rb))};
  }

  double closedForm() const {
    Vector z(4), mean(4);
    z << za, zb;
    mean << values.at<Point2>(a), values.at<Point2>(b);
    Matrix S = covariance;
    S.topLeftCorner(2, 2) += Ra;
    S.bottomRightCorner(2, 2) += Rb;
    return logGaussian(z, mean, S);
  }
};

}  // namespace semslam::test
