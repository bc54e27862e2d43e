#include "semslam/association/MarginalLikelihood.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "semslam/models/Sampling.h"

namespace semslam {
namespace {

/// Tangent offset of each of the marginal's keys in its joint vector.
struct MarginalLayout {
  std::vector<int> offsets;
  std::vector<int> dimensions;
  int total = 0;

  MarginalLayout(const JointMarginal& marginal, const Values& values) {
    for (Key key : marginal.keys()) {
      offsets.push_back(total);
      dimensions.push_back(dimension(values.value(key)));
      total += dimensions.back();
    }
    if (marginal.covariance().rows() != total || marginal.covariance().cols() != total) {
      throw std::invalid_argument("joint marginal's size does not fit its variables' dimensions");
    }
  }
};

int indexIn(const JointMarginal& marginal, Key key) {
  const auto& keys = marginal.keys();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (keys[i] == key) return static_cast<int>(i);
  }
  throw std::invalid_argument("variable " + keyToString(key) + " of a measurement factor is not in the joint marginal");
}

/// Σ_f logNormalizer_f; throws if a factor is not a normalised Gaussian density.
double sumOfLogNormalizers(std::span<const FactorPtr> factors) {
  double sum = 0.0;
  for (const FactorPtr& factor : factors) {
    const std::optional<double> normalizer = factor->logNormalizer();
    if (!normalizer) throw std::invalid_argument("a marginal likelihood needs Gaussian factors (no robust kernel)");
    sum += *normalizer;
  }
  return sum;
}

double logSumExp(const std::vector<double>& terms) {
  double maximum = -std::numeric_limits<double>::infinity();
  for (double t : terms) maximum = std::max(maximum, t);
  if (!std::isfinite(maximum)) return maximum;
  double sum = 0.0;
  for (double t : terms) sum += std::exp(t - maximum);
  return maximum + std::log(sum);
}

}  // namespace

LinearizedLikelihood linearizedLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                          const JointMarginal& marginal) {
  const double normalizers = sumOfLogNormalizers(factors);
  const MarginalLayout layout(marginal, values);
  int rows = 0;
  for (const FactorPtr& factor : factors) rows += factor->errorDimension();

  // Stack r̄ and J over the factors, J's columns in the marginal's tangent order.
  Vector r(rows);
  Matrix J = Matrix::Zero(rows, layout.total);
  LinearizedFactor linearized;
  int row = 0;
  for (const FactorPtr& factor : factors) {
    factor->linearize(values, linearized);
    const int m = factor->errorDimension();
    r.segment(row, m) = linearized.whitenedError;
    for (std::size_t k = 0; k < factor->keys().size(); ++k) {
      const int index = indexIn(marginal, factor->keys()[k]);
      J.block(row, layout.offsets[index], m, layout.dimensions[index]) += linearized.jacobians[k];
    }
    row += m;
  }

  // S = J Σ Jᵀ + I; log p = −½ r̄ᵀ S⁻¹ r̄ − ½ log det S − ½ m log 2π + log|R|, and
  // −½ m log 2π + log|R| = −Σ_f logNormalizer_f.
  Matrix S = J * marginal.covariance() * J.transpose();
  S.diagonal().array() += 1.0;
  const Eigen::LLT<Matrix> llt(S);
  if (llt.info() != Eigen::Success) throw std::invalid_argument("innovation covariance is not positive definite");
  const Vector whitenedInnovation = llt.matrixL().solve(r);
  const double logDetS = 2.0 * llt.matrixLLT().diagonal().array().log().sum();

  LinearizedLikelihood result;
  result.dimension = rows;
  result.innovationChi2 = whitenedInnovation.squaredNorm();
  result.logLikelihood = -0.5 * result.innovationChi2 - 0.5 * logDetS - normalizers;
  return result;
}

SampledLikelihood sampledLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                    const JointMarginal& marginal, int samples, std::mt19937& rng,
                                    const SampleWeight& weight) {
  if (samples < 2) throw std::invalid_argument("sampled likelihood needs at least 2 samples");
  const double normalizers = sumOfLogNormalizers(factors);
  const MarginalLayout layout(marginal, values);
  for (const FactorPtr& factor : factors) {
    for (Key key : factor->keys()) indexIn(marginal, key);
  }
  const Matrix root = gaussianSquareRoot(marginal.covariance());

  // The sample only needs the marginal's variables: a small Values, perturbed in place per draw.
  Values sample;
  for (Key key : marginal.keys()) sample.insert(key, values.value(key));
  std::vector<double> logTerms;
  logTerms.reserve(samples);
  Vector n(layout.total);
  for (int s = 0; s < samples; ++s) {
    for (int i = 0; i < layout.total; ++i) n(i) = standardNormal(rng);
    const Vector delta = root * n;
    for (std::size_t i = 0; i < marginal.keys().size(); ++i) {
      const Key key = marginal.keys()[i];
      sample.update(key, retract(values.value(key), delta.segment(layout.offsets[i], layout.dimensions[i])));
    }
    double logTerm = -normalizers;
    for (const FactorPtr& factor : factors) logTerm -= 0.5 * factor->chi2(sample);
    if (weight) {
      const double w = weight(sample);
      if (!(w >= 0.0) || !std::isfinite(w)) throw std::invalid_argument("sample weight must be finite and >= 0");
      logTerm += w > 0.0 ? std::log(w) : -std::numeric_limits<double>::infinity();
    }
    logTerms.push_back(logTerm);
  }

  // Mean and its standard error, relative to the mean, computed on exp(term − log of the largest term).
  const double logSum = logSumExp(logTerms);
  SampledLikelihood result;
  result.samples = samples;
  result.logLikelihood = logSum - std::log(static_cast<double>(samples));
  if (!std::isfinite(result.logLikelihood)) {
    result.relativeStandardError = std::numeric_limits<double>::infinity();
    return result;
  }
  double sumOfSquares = 0.0;
  for (double t : logTerms) {
    const double ratio = std::exp(t - result.logLikelihood);  // term / mean
    sumOfSquares += (ratio - 1.0) * (ratio - 1.0);
  }
  const double variance = sumOfSquares / (samples - 1);
  result.relativeStandardError = std::sqrt(variance / samples);
  return result;
}

}  // namespace semslam
