#pragma once
// ClassBelief: the belief P(c | l) over the M classes of one landmark (paper B, sec. IV-B), kept from the class
// observations of the detections associated with it.
//
// Math. With P(z | c) the classifier model's likelihood of a detection's semantic part (semanticLikelihoods()):
//   predictive        P(z | l) = Σ_c P(z | c) P(c | l)                       (the semantic factor of B's weights)
//   update, weight w  P(c | l) ← w · P(z | c) P(c | l) / P(z | l) + (1 − w) · P(c | l),   w ∈ [0, 1]
// the posterior when the detection came from l with probability w (Bayes' rule) and otherwise says nothing about
// l (the prior): a proper mixture, continuous in w, Bayes at w = 1 and no change at w = 0. A label that l's belief
// rules out (P(z | l) = 0) leaves it unchanged when w < 1 and throws when w = 1. Stored in log space (the Bayes
// term exactly, the mixture by log-sum-exp), so long runs of confident labels neither underflow nor lock a class
// at exactly probability one.
//
// Invariants: probabilities() has M ≥ 1 entries, finite, ≥ 0, summing to one.

#include "semslam/geometry/Matrix.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

class ClassBelief {
 public:
  /// The uniform belief over `classes` classes.
  explicit ClassBelief(int classes);

  int classes() const { return static_cast<int>(logProbabilities_.size()); }
  Vector probabilities() const;
  double probability(int classIndex) const;
  /// The most probable class (the lowest index on ties).
  int mostProbable() const;

  /// Σ_c P(z | c) P(c | l), given (P(z | c))_c.
  double predictive(const Vector& likelihoods) const;
  /// P(c | l) ← w · Bayes + (1 − w) · P(c | l).
  void update(const Vector& likelihoods, double weight = 1.0);

 private:
  Vector logProbabilities_;  // normalised: log Σ exp = 0
};

/// (P(z | c))_c for a detection's semantic part under the log's categorical classifier model: the confusion
/// column of a label, C z for a probability vector, all ones when the log has no semantics or no categorical
/// model (the viewpoint-dependent Gaussian model of paper A depends on the pose and is a factor, not this).
Vector semanticLikelihoods(const LogHeader& header, const Detection& detection);

}  // namespace semslam
