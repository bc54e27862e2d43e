#pragma once
// CategoricalClassifierModel: the semantic measurement model of paper B (sec. IV): a detector's class output is a
// sample from a categorical distribution whose probabilities are a row of a known confusion matrix, independent
// of the viewpoint and of the object's position.
//
// Math
//   C[c, j] = P(label j | true class c), rows summing to one (c, j ∈ [0, M)). From a misclassification rate p
//   (paper B, sec. V: 1 − p on the diagonal, p / (M − 1) off it):
//       C = (1 − p) I + p / (M − 1) (11ᵀ − I).
//   A class label z ∈ [0, M):                 P(z | c) = C[c, z].
//   A class-probability vector z (z_j ≥ 0, Σ z_j = 1, length M):
//                                             P(z | c) = Σ_j z_j C[c, j] = (C z)_c.
//   The second is the likelihood of a *soft label*: z is read as the classifier's own distribution over which label
//   it would have output, and the likelihood is the label likelihood averaged over it. It reduces to C[c, z] for a
//   one-hot z, is linear in z, and for every z it is a proper mixture, so Σ_c over hypotheses behaves as with
//   labels (decision in docs/models.md; the alternative Π_j C[c, j]^{z_j} is not used).
//
// Invariants: M ≥ 2; p ∈ [0, 1); an explicit matrix is M x M, finite, entries in [0, 1], rows summing to one
// within 1e-9 (they are renormalised exactly). A label is in [0, M); a probability vector has length M, finite
// entries ≥ −1e-9 that sum to one within 1e-3 (classifier outputs printed with few digits). Anything else throws
// std::invalid_argument naming the problem. Log-likelihoods of impossible outcomes (C[c, z] = 0, e.g. p = 0) are
// −∞.

#include <random>

#include "semslam/geometry/Matrix.h"

namespace semslam {

class CategoricalClassifierModel {
 public:
  /// C = (1 − p) I + p/(M − 1) (11ᵀ − I).
  CategoricalClassifierModel(int classes, double misclassification);
  /// An explicit confusion matrix, C[c, j] = P(label j | class c).
  explicit CategoricalClassifierModel(const Matrix& confusion);

  int classes() const { return static_cast<int>(confusion_.rows()); }
  const Matrix& confusion() const { return confusion_; }

  /// P(label | c) = C[c, label].
  double likelihood(int label, int classIndex) const;
  /// P(z | c) = Σ_j z_j C[c, j] for a class-probability vector z.
  double likelihood(const Vector& probabilities, int classIndex) const;
  double logLikelihood(int label, int classIndex) const;
  double logLikelihood(const Vector& probabilities, int classIndex) const;

  /// (P(label | c))_c for every class c: the column C[:, label].
  Vector likelihoods(int label) const;
  /// (P(z | c))_c for every class c: C z.
  Vector likelihoods(const Vector& probabilities) const;

  /// A label drawn from row c of C (inverse CDF on uniform01, Sampling.h: same seed, same label).
  int sampleLabel(int classIndex, std::mt19937& rng) const;

 private:
  void checkClass(int classIndex) const;
  void checkLabel(int label) const;
  void checkProbabilities(const Vector& probabilities) const;

  Matrix confusion_;
};

}  // namespace semslam
