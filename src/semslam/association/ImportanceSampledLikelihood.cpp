#include "semslam/association/ImportanceSampledLikelihood.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "semslam/models/Sampling.h"

namespace semslam {
namespace {

constexpr double kNegativeInfinity = -std::numeric_limits<double>::infinity();

/// The marginal's keys with their tangent offsets and dimensions.
struct TangentLayout {
  std::vector<int> offsets, dimensions;
  int total = 0;

  TangentLayout(const JointMarginal& marginal, const Values& values) {
    for (Key key : marginal.keys()) {
      offsets.push_back(total);
      dimensions.push_back(dimension(values.value(key)));
      total += dimensions.back();
    }
    if (marginal.covariance().rows() != total || marginal.covariance().cols() != total) {
      throw std::invalid_argument("joint marginal's size does not fit its variables' dimensions");
    }
  }

  int indexOf(const JointMarginal& marginal, Key key) const {
    const auto& keys = marginal.keys();
    const auto it = std::find(keys.begin(), keys.end(), key);
    if (it == keys.end()) {
      throw std::invalid_argument("variable " + keyToString(key) + " of a measurement factor is not in the joint marginal");
    }
    return static_cast<int>(it - keys.begin());
  }
};

/// r̄ and J of the stacked whitened factors at `values`, J's columns in the layout's tangent order.
struct StackedLinearization {
  Vector r;
  Matrix J;
};

StackedLinearization stack(std::span<const FactorPtr> factors, const Values& values, const JointMarginal& marginal,
                           const TangentLayout& layout) {
  int rows = 0;
  for (const FactorPtr& factor : factors) rows += factor->errorDimension();
  StackedLinearization s{Vector(rows), Matrix::Zero(rows, layout.total)};
  LinearizedFactor linearized;
  int row = 0;
  for (const FactorPtr& factor : factors) {
    factor->linearize(values, linearized);
    const int m = factor->errorDimension();
    s.r.segment(row, m) = linearized.whitenedError;
    for (std::size_t k = 0; k < factor->keys().size(); ++k) {
      const int index = layout.indexOf(marginal, factor->keys()[k]);
      s.J.block(row, layout.offsets[index], m, layout.dimensions[index]) += linearized.jacobians[k];
    }
    row += m;
  }
  return s;
}

/// The proposal N(δ', Σ') and the constant −½ log det S of the log importance weights.
struct LinearizedPosterior {
  Vector mean;          ///< δ'
  Matrix root;          ///< L', L' L'ᵀ = Σ'
  double halfLogDetS = 0.0;
};

/// The Gaussian update with r(δ) ≈ s.r + s.J (δ − at): δ' = −K (s.r − s.J at), Σ' = Σ − K J Σ.
LinearizedPosterior linearizedPosterior(const Matrix& covariance, const StackedLinearization& s, const Vector& at) {
  const Matrix JSigma = s.J * covariance;  // J Σ
  Matrix S = JSigma * s.J.transpose();
  S.diagonal().array() += 1.0;
  const Eigen::LLT<Matrix> llt(S);
  if (llt.info() != Eigen::Success) throw std::invalid_argument("innovation covariance is not positive definite");
  const Matrix gainT = llt.solve(JSigma);  // Kᵀ = S⁻¹ J Σ
  Matrix posterior = covariance - JSigma.transpose() * gainT;  // Σ − K J Σ
  posterior = 0.5 * (posterior + posterior.transpose());
  LinearizedPosterior p;
  p.mean = -gainT.transpose() * (s.r - s.J * at);
  p.root = gaussianSquareRoot(posterior);
  p.halfLogDetS = llt.matrixLLT().diagonal().array().log().sum();
  return p;
}

/// X̄ ⊕ δ into `sample` (which holds the marginal's keys).
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

/// Mean of exp(terms) in logs and its relative standard error.
SampledLikelihood meanOfExponentials(const std::vector<double>& logTerms) {
  const int n = static_cast<int>(logTerms.size());
  double maximum = kNegativeInfinity;
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

}  // namespace

SampledLikelihood importanceSampledLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                              const JointMarginal& marginal, int samples, std::mt19937& rng,
                                              const SampleWeight& weight, const ImportanceProposal& proposal_) {
  if (proposal_.iterations < 1) throw std::invalid_argument("importance proposal needs at least 1 linearisation");
  if (samples < 2) throw std::invalid_argument("importance-sampled likelihood needs at least 2 samples");
  const double normalizers = sumOfLogNormalizers(factors);
  const TangentLayout layout(marginal, values);
  const Eigen::LLT<Matrix> prior(marginal.covariance());
  if (prior.info() != Eigen::Success) throw std::invalid_argument("importance sampling needs a positive definite Σ");
  Values sample;
  for (Key key : marginal.keys()) sample.insert(key, values.value(key));

  // Iteration 1 linearises at the mean; each further one relinearises at the previous proposal mean (iterated
  // update), keeping the proposal whose mean has the lowest negative log posterior φ(δ) = ½ Σ χ² + ½ |L⁻¹ δ|².
  const auto phi = [&](const Vector& delta) {
    retractInto(sample, values, marginal, layout, delta);
    double value = 0.5 * prior.matrixL().solve(delta).squaredNorm();
    for (const FactorPtr& factor : factors) value += 0.5 * factor->chi2(sample);
    return value;
  };
  Vector at = Vector::Zero(layout.total);
  LinearizedPosterior proposal = linearizedPosterior(marginal.covariance(), stack(factors, values, marginal, layout), at);
  double best = phi(proposal.mean);
  for (int iteration = 1; iteration < proposal_.iterations; ++iteration) {
    at = proposal.mean;
    retractInto(sample, values, marginal, layout, at);
    LinearizedPosterior next = linearizedPosterior(marginal.covariance(), stack(factors, sample, marginal, layout), at);
    const double value = phi(next.mean);
    if (!(value < best)) break;
    best = value;
    proposal = std::move(next);
  }

  std::vector<double> logTerms;
  logTerms.reserve(samples);
  Vector n(layout.total);
  for (int s = 0; s < samples; ++s) {
    for (int i = 0; i < layout.total; ++i) n(i) = standardNormal(rng);
    const Vector delta = proposal.mean + proposal.root * n;
    retractInto(sample, values, marginal, layout, delta);
    // log p(z | X_s) + log N(δ_s; 0, Σ) − log N(δ_s; δ', Σ')
    double logTerm = -normalizers - proposal.halfLogDetS + 0.5 * n.squaredNorm() -
                     0.5 * prior.matrixL().solve(delta).squaredNorm();
    for (const FactorPtr& factor : factors) logTerm -= 0.5 * factor->chi2(sample);
    if (weight) {
      const double w = weight(sample);
      if (!(w >= 0.0) || !std::isfinite(w)) throw std::invalid_argument("sample weight must be finite and >= 0");
      logTerm += w > 0.0 ? std::log(w) : kNegativeInfinity;
    }
    logTerms.push_back(logTerm);
  }
  return meanOfExponentials(logTerms);
}

}  // namespace semslam
