#include "semslam/association/ImportanceSampledLikelihood.h"

#include <stdexcept>
#include <vector>

#include "semslam/association/LikelihoodTerms.h"
#include "semslam/models/Sampling.h"

namespace semslam {
namespace {

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
  LinearizedPosterior proposal = linearizedPosterior(marginal.covariance(), stackFactors(factors, values, marginal, layout), at);
  double best = phi(proposal.mean);
  for (int iteration = 1; iteration < proposal_.iterations; ++iteration) {
    at = proposal.mean;
    retractInto(sample, values, marginal, layout, at);
    LinearizedPosterior next = linearizedPosterior(marginal.covariance(), stackFactors(factors, sample, marginal, layout), at);
    const double value = phi(next.mean);
    if (!(value < best)) break;
    best = value;
    proposal = std::move(next);
  }

  Vector logTerms(samples);
  const Matrix normals = standardNormalMatrix(layout.total, samples, rng);
  for (int s = 0; s < samples; ++s) {
    const auto n = normals.col(s);
    const Vector delta = proposal.mean + proposal.root * n;
    retractInto(sample, values, marginal, layout, delta);
    // The integrand of (A, eq. 16) at X_s over the proposal: log p(z | X_s) + log N(δ_s; 0, Σ) − log N(δ_s; δ', Σ')
    double logTerm = -normalizers - proposal.halfLogDetS + 0.5 * n.squaredNorm() -
                     0.5 * prior.matrixL().solve(delta).squaredNorm();
    for (const FactorPtr& factor : factors) logTerm -= 0.5 * factor->chi2(sample);
    logTerms(s) = logTerm + logSampleWeight(weight, sample);
  }
  return meanOfExponentials(logTerms);
}

}  // namespace semslam
