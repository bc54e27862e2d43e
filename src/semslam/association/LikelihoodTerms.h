#pragma once
// The pieces both marginal-likelihood estimators share (MarginalLikelihood.cpp: linearised and plain Monte Carlo;
// ImportanceSampledLikelihood.cpp): the joint marginal's tangent layout, the stacked whitened linearisation of a
// measurement's factors, perturbing the estimate by a joint tangent vector, the Gaussian normalisers, the
// per-sample weight, and the log-space mean of sampled terms with its relative standard error.

#include <span>
#include <vector>

#include "semslam/association/MarginalLikelihood.h"

namespace semslam {

/// The marginal's keys with their tangent offsets and dimensions (JointMarginal's key order).
struct TangentLayout {
  std::vector<int> offsets, dimensions;
  int total = 0;

  /// Throws std::invalid_argument when the marginal's size does not fit its variables' dimensions.
  TangentLayout(const JointMarginal& marginal, const Values& values);
  /// The position of `key` in the marginal; throws std::invalid_argument when it is not there.
  static int indexOf(const JointMarginal& marginal, Key key);
};

/// r̄ and J of the factors stacked at `values`, J's columns in the layout's tangent order.
struct StackedLinearization {
  Vector r;
  Matrix J;
};
StackedLinearization stackFactors(std::span<const FactorPtr> factors, const Values& values,
                                  const JointMarginal& marginal, const TangentLayout& layout);

/// X̄ ⊕ δ into `sample`, which holds the marginal's keys.
void retractInto(Values& sample, const Values& values, const JointMarginal& marginal, const TangentLayout& layout,
                 const Vector& delta);

/// Σ_f logNormalizer_f; throws std::invalid_argument for a factor that is not a normalised Gaussian.
double sumOfLogNormalizers(std::span<const FactorPtr> factors);

/// log w(X) of a per-sample weight (0 for an empty one); throws for a negative or non-finite weight.
double logSampleWeight(const SampleWeight& weight, const Values& sample);

/// log of the mean of exp(terms) (log-sum-exp) and the mean's relative standard error; at least 2 terms.
SampledLikelihood meanOfExponentials(const Vector& logTerms);

}  // namespace semslam
