#include "semslam/models/ViewpointClassifierModel.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "semslam/models/Sampling.h"

namespace semslam {

SharedNoiseModel ViewpointClassifierModel::noiseModel(int classIndex, double theta) const {
  return NoiseModel::fromCovariance(covariance(classIndex, theta));
}

double ViewpointClassifierModel::logLikelihood(const Vector& z, int classIndex, double theta) const {
  checkClass(classIndex);
  if (z.size() != dimension()) {
    throw std::invalid_argument("viewpoint classifier: the measurement has " + std::to_string(z.size()) +
                                " entries, the model " + std::to_string(dimension()));
  }
  if (!z.allFinite()) throw std::invalid_argument("viewpoint classifier: the measurement has a NaN or infinity");
  const SharedNoiseModel noise = noiseModel(classIndex, theta);
  Vector error = z - mean(classIndex, theta);
  noise->whitenInPlace(error);
  return -0.5 * error.squaredNorm() - noise->logNormalizer();
}

Vector ViewpointClassifierModel::sample(int classIndex, double theta, std::mt19937& rng) const {
  checkClass(classIndex);
  return sampleGaussian(mean(classIndex, theta), covariance(classIndex, theta), rng);
}

void ViewpointClassifierModel::checkClass(int classIndex) const {
  if (classIndex < 0 || classIndex >= classes()) {
    throw std::invalid_argument("viewpoint classifier: class index " + std::to_string(classIndex) +
                                " is outside [0, " + std::to_string(classes()) + ")");
  }
}

void ViewpointClassifierModel::checkTheta(double theta) {
  if (!std::isfinite(theta)) throw std::invalid_argument("viewpoint classifier: the viewpoint angle is not finite");
}

}  // namespace semslam
