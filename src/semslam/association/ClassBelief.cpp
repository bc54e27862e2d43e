#include "semslam/association/ClassBelief.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "semslam/models/CategoricalClassifierModel.h"

namespace semslam {

ClassBelief::ClassBelief(int classes) {
  if (classes < 1) throw std::invalid_argument("a class belief needs at least one class");
  logProbabilities_ = Vector::Constant(classes, -std::log(static_cast<double>(classes)));
}

Vector ClassBelief::probabilities() const { return logProbabilities_.array().exp(); }

double ClassBelief::probability(int classIndex) const {
  if (classIndex < 0 || classIndex >= classes()) throw std::invalid_argument("class index out of range");
  return std::exp(logProbabilities_(classIndex));
}

int ClassBelief::mostProbable() const {
  Eigen::Index best = 0;
  logProbabilities_.maxCoeff(&best);
  return static_cast<int>(best);
}

double ClassBelief::predictive(const Vector& likelihoods) const {
  if (likelihoods.size() != classes()) throw std::invalid_argument("likelihood vector does not have one entry per class");
  return probabilities().dot(likelihoods);
}

void ClassBelief::update(const Vector& likelihoods, double weight) {
  if (likelihoods.size() != classes()) throw std::invalid_argument("likelihood vector does not have one entry per class");
  if (!(weight >= 0.0 && weight <= 1.0)) throw std::invalid_argument("association weight must be in [0, 1]");
  if (weight == 0.0) return;
  Vector updated = logProbabilities_;
  for (int c = 0; c < classes(); ++c) {
    if (!(likelihoods(c) >= 0.0) || !std::isfinite(likelihoods(c))) {
      throw std::invalid_argument("class likelihoods must be finite and >= 0");
    }
    updated(c) += weight * std::log(likelihoods(c));
  }
  const double maximum = updated.maxCoeff();
  if (!std::isfinite(maximum)) throw std::invalid_argument("a detection impossible under every class");
  const double logNormalizer = maximum + std::log((updated.array() - maximum).exp().sum());
  logProbabilities_ = updated.array() - logNormalizer;
}

Vector semanticLikelihoods(const LogHeader& header, const Detection& detection) {
  const Vector uniform = Vector::Ones(header.classes);
  if (header.semantic == SemanticKind::None || header.classifier.kind != ClassifierModelSpec::Kind::Categorical) {
    return uniform;
  }
  const CategoricalClassifierModel model(header.classes, header.classifier.misclassification);
  if (header.semantic == SemanticKind::Label) {
    if (!detection.label) throw std::invalid_argument("detection has no class label");
    return model.likelihoods(*detection.label);
  }
  if (header.semantic == SemanticKind::Probabilities) {
    if (!detection.classVector) throw std::invalid_argument("detection has no class-probability vector");
    return model.likelihoods(*detection.classVector);
  }
  return uniform;
}

}  // namespace semslam
