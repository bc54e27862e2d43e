#include "semslam/association/MarginalLikelihood.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "semslam/association/LikelihoodTerms.h"
#include "semslam/models/Sampling.h"

namespace semslam {

LinearizedLikelihood linearizedLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                          const JointMarginal& marginal) {
  const double normalizers = sumOfLogNormalizers(factors);
  const TangentLayout layout(marginal, values);
  const StackedLinearization stacked = stackFactors(factors, values, marginal, layout);

  // The closed form log N(z; h(X̄), H Σ Hᵀ + Σ_z) (B, sec. IV-B) of the integral (A, eq. 16-17), whitened:
  // S = J Σ Jᵀ + I; log p = −½ r̄ᵀ S⁻¹ r̄ − ½ log det S − ½ m log 2π + log|R|, and
  // −½ m log 2π + log|R| = −Σ_f logNormalizer_f.
  Matrix S = stacked.J * marginal.covariance() * stacked.J.transpose();
  S.diagonal().array() += 1.0;
  const Eigen::LLT<Matrix> llt(S);
  if (llt.info() != Eigen::Success) throw std::invalid_argument("innovation covariance is not positive definite");
  const Vector whitenedInnovation = llt.matrixL().solve(stacked.r);
  const double logDetS = 2.0 * llt.matrixLLT().diagonal().array().log().sum();

  LinearizedLikelihood result;
  result.dimension = static_cast<int>(stacked.r.size());
  result.innovationChi2 = whitenedInnovation.squaredNorm();
  result.logLikelihood = -0.5 * result.innovationChi2 - 0.5 * logDetS - normalizers;
  return result;
}

MarginalSamples::MarginalSamples(const Values& values, const JointMarginal& marginal, int samples,
                                 std::mt19937& rng)
    : samples_(samples), keys_(marginal.keys()) {
  if (samples < 2) throw std::invalid_argument("sampled likelihood needs at least 2 samples");
  const TangentLayout layout(marginal, values);
  const Matrix offsets = gaussianSquareRoot(marginal.covariance()) * standardNormalMatrix(layout.total, samples, rng);
  drawn_.reserve(keys_.size() * static_cast<std::size_t>(samples));
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    const Value& mean = values.value(keys_[i]);
    for (int s = 0; s < samples; ++s) {
      drawn_.push_back(retract(mean, offsets.col(s).segment(layout.offsets[i], layout.dimensions[i])));
    }
  }
}

std::size_t MarginalSamples::slot(Key key) const {
  const auto found = std::find(keys_.begin(), keys_.end(), key);
  if (found == keys_.end()) throw std::invalid_argument("sampled likelihood: a factor's variable is not drawn");
  return static_cast<std::size_t>(found - keys_.begin());
}

bool MarginalSamples::holds(Key key) const { return std::find(keys_.begin(), keys_.end(), key) != keys_.end(); }

const Value& MarginalSamples::draw(Key key, int s) const {
  return drawn_[slot(key) * static_cast<std::size_t>(samples_) + static_cast<std::size_t>(s)];
}

Vector sampledLogTerms(std::span<const FactorPtr> factors, const MarginalSamples& samples,
                       const SampleWeight& weight) {
  const double normalizers = sumOfLogNormalizers(factors);
  // The sample holds the factors' variables only, each retracted in place per draw.
  std::vector<Key> keys;
  for (const FactorPtr& factor : factors) {
    for (Key key : factor->keys()) {
      if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
      if (!samples.holds(key)) throw std::invalid_argument("sampled likelihood: a factor's variable is not drawn");
      keys.push_back(key);
    }
  }
  Values sample;
  for (Key key : keys) sample.insert(key, samples.draw(key, 0));
  // log P(Z | X_s) + log P(β | X_s), X_s drawn from the joint marginal (A, eq. 16-17).
  Vector logTerms(samples.size());
  for (int s = 0; s < samples.size(); ++s) {
    for (Key key : keys) sample.update(key, samples.draw(key, s));
    double logTerm = -normalizers;
    for (const FactorPtr& factor : factors) logTerm -= 0.5 * factor->chi2(sample);
    logTerms(s) = logTerm + logSampleWeight(weight, sample);
  }
  return logTerms;
}

SampledLikelihood sampledLikelihood(std::span<const FactorPtr> factors, const MarginalSamples& samples,
                                    const SampleWeight& weight) {
  // p(z | H) ≈ (1/n) Σ_s P(Z | X_s) P(β | X_s) (A, eq. 16-17).
  return meanOfExponentials(sampledLogTerms(factors, samples, weight));
}

SampledLikelihood sampledLikelihood(std::span<const FactorPtr> factors, const Values& values,
                                    const JointMarginal& marginal, int samples, std::mt19937& rng,
                                    const SampleWeight& weight) {
  return sampledLikelihood(factors, MarginalSamples(values, marginal, samples, rng), weight);
}

}  // namespace semslam
