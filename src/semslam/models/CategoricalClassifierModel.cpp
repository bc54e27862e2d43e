#include "semslam/models/CategoricalClassifierModel.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "semslam/models/Sampling.h"

namespace semslam {

namespace {

const std::string kName = "CategoricalClassifierModel: ";

Matrix uniformConfusion(int classes, double p) {
  if (classes < 2) throw std::invalid_argument(kName + "at least 2 classes are needed, got " + std::to_string(classes));
  if (!std::isfinite(p) || p < 0.0 || p >= 1.0) {
    throw std::invalid_argument(kName + "the misclassification rate must be in [0, 1), got " + std::to_string(p));
  }
  Matrix C = Matrix::Constant(classes, classes, p / (classes - 1));
  C.diagonal().setConstant(1.0 - p);
  return C;
}

}  // namespace

CategoricalClassifierModel::CategoricalClassifierModel(int classes, double misclassification)
    : confusion_(uniformConfusion(classes, misclassification)) {}

CategoricalClassifierModel::CategoricalClassifierModel(const Matrix& confusion) : confusion_(confusion) {
  const Eigen::Index m = confusion.rows();
  if (m < 2 || confusion.cols() != m) {
    throw std::invalid_argument(kName + "the confusion matrix must be square with at least 2 classes, got " +
                                std::to_string(confusion.rows()) + "x" + std::to_string(confusion.cols()));
  }
  if (!confusion.allFinite()) throw std::invalid_argument(kName + "the confusion matrix has a NaN or infinity");
  if ((confusion.array() < 0.0).any() || (confusion.array() > 1.0).any()) {
    throw std::invalid_argument(kName + "confusion matrix entries must be in [0, 1]");
  }
  for (Eigen::Index c = 0; c < m; ++c) {
    const double sum = confusion.row(c).sum();
    if (std::abs(sum - 1.0) > 1e-9) {
      throw std::invalid_argument(kName + "row " + std::to_string(c) + " of the confusion matrix sums to " +
                                  std::to_string(sum) + ", not 1");
    }
    confusion_.row(c) /= sum;
  }
}

void CategoricalClassifierModel::checkClass(int classIndex) const {
  if (classIndex < 0 || classIndex >= classes()) {
    throw std::invalid_argument(kName + "class index " + std::to_string(classIndex) + " is outside [0, " +
                                std::to_string(classes()) + ")");
  }
}

void CategoricalClassifierModel::checkLabel(int label) const {
  if (label < 0 || label >= classes()) {
    throw std::invalid_argument(kName + "label " + std::to_string(label) + " is outside [0, " +
                                std::to_string(classes()) + ")");
  }
}

void CategoricalClassifierModel::checkProbabilities(const Vector& z) const {
  if (z.size() != classes()) {
    throw std::invalid_argument(kName + "the probability vector has " + std::to_string(z.size()) +
                                " entries, the model " + std::to_string(classes()) + " classes");
  }
  if (!z.allFinite() || (z.array() < -1e-9).any()) {
    throw std::invalid_argument(kName + "probability vector entries must be finite and >= 0");
  }
  if (std::abs(z.sum() - 1.0) > 1e-3) {
    throw std::invalid_argument(kName + "the probability vector sums to " + std::to_string(z.sum()) + ", not 1");
  }
}

double CategoricalClassifierModel::likelihood(int label, int classIndex) const {
  checkLabel(label);
  checkClass(classIndex);
  return confusion_(classIndex, label);
}

double CategoricalClassifierModel::likelihood(const Vector& probabilities, int classIndex) const {
  checkProbabilities(probabilities);
  checkClass(classIndex);
  return confusion_.row(classIndex).dot(probabilities.cwiseMax(0.0));
}

double CategoricalClassifierModel::logLikelihood(int label, int classIndex) const {
  return std::log(likelihood(label, classIndex));
}

double CategoricalClassifierModel::logLikelihood(const Vector& probabilities, int classIndex) const {
  return std::log(likelihood(probabilities, classIndex));
}

Vector CategoricalClassifierModel::likelihoods(int label) const {
  checkLabel(label);
  return confusion_.col(label);
}

Vector CategoricalClassifierModel::likelihoods(const Vector& probabilities) const {
  checkProbabilities(probabilities);
  return confusion_ * probabilities.cwiseMax(0.0);
}

int CategoricalClassifierModel::sampleLabel(int classIndex, std::mt19937& rng) const {
  checkClass(classIndex);
  const double u = uniform01(rng);
  double cumulative = 0.0;
  int last = 0;
  for (int j = 0; j < classes(); ++j) {
    const double pj = confusion_(classIndex, j);
    if (pj <= 0.0) continue;
    last = j;
    cumulative += pj;
    if (u < cumulative) return j;
  }
  return last;  // u within rounding of 1: the last label with non-zero probability
}

}  // namespace semslam
