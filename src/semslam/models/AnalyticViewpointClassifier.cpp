#include "semslam/models/AnalyticViewpointClassifier.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace semslam {

AnalyticViewpointClassifier::AnalyticViewpointClassifier(double alpha, double sharpness, int classes)
    : alpha_(alpha), sharpness_(sharpness) {
  if (classes != 2) {
    throw std::invalid_argument(
        "AnalyticViewpointClassifier: paper A's model (eq. 18) is defined for 2 classes, got " +
        std::to_string(classes) + " (use a tabulated model for other class counts)");
  }
  if (!std::isfinite(alpha) || alpha < 0.0 || alpha > 1.0) {
    throw std::invalid_argument("AnalyticViewpointClassifier: alpha must be in [0, 1], got " +
                                std::to_string(alpha));
  }
  if (!std::isfinite(sharpness) || sharpness <= 0.0) {
    throw std::invalid_argument("AnalyticViewpointClassifier: K must be finite and > 0, got " +
                                std::to_string(sharpness));
  }
  Matrix R(2, 2);
  R << sharpness, -0.5 * sharpness, 0.0, sharpness;
  noise_ = NoiseModel::fromSqrtInformation(R);
}

Vector AnalyticViewpointClassifier::mean(int classIndex, double theta, Vector* dMeanDTheta) const {
  checkClass(classIndex);
  checkTheta(theta);
  const double half = std::sin(0.5 * theta);
  const double s = half * half;
  Vector h(2);
  h << alpha_ * s + (1.0 - alpha_), alpha_ - alpha_ * s;
  const double slope = 0.5 * alpha_ * std::sin(theta);
  if (dMeanDTheta) {
    dMeanDTheta->resize(2);
    *dMeanDTheta << slope, -slope;
  }
  if (classIndex == 1) {
    std::swap(h(0), h(1));
    if (dMeanDTheta) std::swap((*dMeanDTheta)(0), (*dMeanDTheta)(1));
  }
  return h;
}

Matrix AnalyticViewpointClassifier::covariance(int classIndex, double theta) const {
  checkClass(classIndex);
  checkTheta(theta);
  return noise_->covariance();
}

SharedNoiseModel AnalyticViewpointClassifier::noiseModel(int classIndex, double theta) const {
  checkClass(classIndex);
  checkTheta(theta);
  return noise_;
}

}  // namespace semslam
