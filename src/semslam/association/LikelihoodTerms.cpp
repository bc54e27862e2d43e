#include "semslam/association/LikelihoodTerms.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace semslam {

TangentLayout::TangentLayout(const JointMarginal& marginal, const Values& values) {
  for (Key key : marginal.keys()) {
    offsets.push_back(total);
    dimensions.push_back(dimension(values.value(key)));
    total += dimensions.back();
  }
  if (marginal.covariance().rows() != total || marginal.covariance().cols() != total) {
    throw std::invalid_argument("joint marginal's size does not fit its variables' dimensions");
  }
}

int TangentLayout::indexOf(const JointMarginal& marginal, Key key) {
  const auto& keys = marginal.keys();
  const auto it = std::find(keys.begin(), keys.end(), key);
  if (it == keys.end()) {
    throw std::invalid_argument("variable " + keyToString(key) + " of a measurement factor is not in the joint marginal");
  }
  return static_cast<int>(it - keys.begin());
}

StackedLinearization stackFactors(std::span<const FactorPtr> factors, const Values& values,
                                  const JointMarginal& marginal, const TangentLayout& layout) {
  int rows = 0;
  for (const FactorPtr& factor : factors) rows += factor->errorDimension();
  StackedLinearization stacked{Vector(rows), Matrix::Zero(rows, layout.total)};
  LinearizedFactor linearized;
  int row = 0;
  for (const FactorPtr& factor : factors) {
    factor->linearize(values, linearized);
    const int m = factor->errorDimension();
    stacked.r.segment(row, m) = linearized.whitenedError;
    for (std::size_t k = 0; k < factor->keys().size(); ++k) {
      const int index = TangentLayout::indexOf(marginal, factor->keys()[k]);
      stacked.J.block(row, layout.offsets[index], m, layout.dimensions[index]) += linearized.jacobians[k];
    }
    row += m;
  }
  return stacked;
}

void retractInto(Values& sample, const Values& values, const JointMarginal& marginal, const TangentLayout& layout,
                 const Vector& delta) {
  for (std::size_t i = 0; i < marginal.keys().size(); ++i) {
    const Key key = marginal.keys()[i];
    sample.update(key, retract(values.value(key), delta.segment(layout.offsets[i], layout.dimensions[i])));
  }
}

double sumOfLogNormalizers(std::span<const FactorPtr> factors) {
  double sum = 0.0;
  for (const FactorPtr& factor : factors) {
    const std::optional<double> normalizer = factor->logNormalizer();
    if (!normalizer) throw std::invalid_argument("a marginal likelihood needs Gaussian factors (no robust kernel)");
    sum += *normalizer;
  }
  return sum;
}

double logSampleWeight(const SampleWeight& weight, const Values& sample) {
  if (!weight) return 0.0;
  const double w = weight(sample);
  if (!(w >= 0.0) || !std::isfinite(w)) throw std::invalid_argument("sample weight must be finite and >= 0");
  return w > 0.0 ? std::log(w) : -std::numeric_limits<double>::infinity();
}

SampledLikelihood meanOfExponentials(const Vector& logTerms) {
  const int n = static_cast<int>(logTerms.size());
  double maximum = -std::numeric_limits<double>::infinity();
  for (double t : logTerms) maximum = std::max(maximum, t);
  SampledLikelihood result;
  result.samples = n;
  if (!std::isfinite(maximum)) {
    result.logLikelihood = maximum;
    result.relativeStandardError = std::numeric_limits<double>::infinity();
    return result;
  }
  double sum = 0.0;
  for (double t : logTerms) sum += std::exp(t - maximum);
  result.logLikelihood = maximum + std::log(sum / n);
  double sumOfSquares = 0.0;
  for (double t : logTerms) {
    const double ratio = std::exp(t - result.logLikelihood);  // term / mean
    sumOfSquares += (ratio - 1.0) * (ratio - 1.0);
  }
  result.relativeStandardError = std::sqrt(sumOfSquares / (n - 1) / n);
  return result;
}

}  // namespace semslam
