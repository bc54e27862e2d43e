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

Vector ClassBelief::probabilities() const {
  // Scalar std::exp: Eigen's vectorised exp clamps its argument, so exp(−∞) would come out as 5.6e-309, not 0,
  // and a class the belief has ruled out would keep a sliver of probability.
  Vector probabilities(classes());
  for (int c = 0; c < classes(); ++c) probabilities(c) = std::exp(logProbabilities_(c));
  return probabilities;
}

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
  for (int c = 0; c < classes(); ++c) {
    if (!(likelihoods(c) >= 0.0) || !std::isfinite(likelihoods(c))) {
      throw std::invalid_argument("class likelihoods must be finite and >= 0");
    }
  }
  if (weight == 0.0) return;
  // Bayes' posterior in log space (B, sec. IV-B): log P(c | l) + log P(z | c) − log P(z | l).
  Vector bayes = logProbabilities_ + likelihoods.array().log().matrix();
  const double maximum = bayes.maxCoeff();
  if (!std::isfinite(maximum)) {
    // P(z | l) = 0: the detection cannot come from l. With w < 1 it did not (the posterior is the prior).
    if (weight < 1.0) return;
    throw std::invalid_argument("a detection impossible under every class of its landmark");
  }
  bayes = bayes.array() - (maximum + std::log((bayes.array() - maximum).exp().sum()));
  if (weight == 1.0) {
    logProbabilities_ = bayes;
    return;
  }
  // w · Bayes + (1 − w) · prior, each term in log space.
  const double logWeight = std::log(weight), logComplement = std::log1p(-weight);
  for (int c = 0; c < classes(); ++c) {
    const double a = logWeight + bayes(c), b = logComplement + logProbabilities_(c);
    const double larger = std::max(a, b);
    logProbabilities_(c) = std::isfinite(larger) ? larger + std::log(std::exp(a - larger) + std::exp(b - larger)) : larger;
  }
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
