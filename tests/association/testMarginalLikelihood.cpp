// The one component likelihood of both papers (association/MarginalLikelihood.h): exact on a linear-Gaussian
// problem, the Monte Carlo version within its own standard error, and the innovation chi2 the gate uses.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "semslam/association/MarginalLikelihood.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/graph/NoiseModel.h"
#include "association/LinearToy.h"

using namespace semslam;
using semslam::test::LinearToy;
using semslam::test::logGaussian;

namespace {

}  // namespace

TEST(LinearizedLikelihood, IsExactOnALinearGaussianProblemWithCorrelatedVariables) {
  const LinearToy toy;
  const LinearizedLikelihood result = linearizedLikelihood(toy.factors, toy.values, toy.marginal);
  EXPECT_NEAR(result.logLikelihood, toy.closedForm(), 1e-12);
  EXPECT_EQ(result.dimension, 4);
}

TEST(LinearizedLikelihood, InnovationChi2IsTheMahalanobisDistance) {
  const LinearToy toy;
  const std::vector<FactorPtr> one = {toy.factors[0]};
  const JointMarginal marginal({toy.a}, {2}, toy.covariance.topLeftCorner(2, 2));
  const LinearizedLikelihood result = linearizedLikelihood(one, toy.values, marginal);
  const Vector2 innovation = toy.za - toy.values.at<Point2>(toy.a);
  const Matrix S = toy.covariance.topLeftCorner(2, 2) + toy.Ra;
  EXPECT_NEAR(result.innovationChi2, innovation.dot(S.llt().solve(innovation)), 1e-12);
}

TEST(LinearizedLikelihood, WithoutStateUncertaintyIsTheMeasurementDensity) {
  // Σ = 0: p(z | H) = N(z; h(X̄), R) for a nonlinear factor too.
  const Key x = poseKey(0), l = landmarkKey(0);
  Values values;
  values.insert(x, SE2(0.5, -0.2, 0.3));
  values.insert(l, Point2(4.0, 2.0));
  const Vector2 sigmas(0.1, 0.02);
  const Vector2 z(4.1, 0.2);
  const auto factor = std::make_shared<const RangeBearingFactor<Point2>>(x, l, z, NoiseModel::fromSigmas(sigmas));
  const std::vector<FactorPtr> factors = {factor};
  const LinearizedLikelihood result =
      linearizedLikelihood(factors, values, JointMarginal({x, l}, {3, 2}, Matrix::Zero(5, 5)));
  const Vector2 predicted = RangeBearingSensor2().predict(values.at<SE2>(x), values.at<Point2>(l));
  EXPECT_NEAR(result.logLikelihood, logGaussian(z, predicted, Matrix(sigmas.cwiseAbs2().asDiagonal())), 1e-9);
}

TEST(SampledLikelihood, MatchesTheClosedFormWithinItsMonteCarloError) {
  const LinearToy toy;
  std::mt19937 rng(11);
  const SampledLikelihood sampled = sampledLikelihood(toy.factors, toy.values, toy.marginal, 20000, rng);
  EXPECT_EQ(sampled.samples, 20000);
  EXPECT_GT(sampled.relativeStandardError, 0.0);
  EXPECT_LT(sampled.relativeStandardError, 0.05);
  // log(mean) against log(truth): |Δ| ≈ relative error; 4 standard errors.
  EXPECT_NEAR(sampled.logLikelihood, toy.closedForm(), 4.0 * sampled.relativeStandardError);
}

TEST(SampledLikelihood, ErrorsAreCalibratedOverManySeeds) {
  // Over 200 seeds with 200 samples each, |error| / standard error must behave like |N(0, 1)|: about 5 % above
  // 1.96, i.e. 10 of 200; at most 20 allows for binomial noise (P(X > 20) < 0.002 for X ~ Bin(200, 0.05)).
  const LinearToy toy;
  const double truth = toy.closedForm();
  int outside = 0;
  for (unsigned seed = 0; seed < 200; ++seed) {
    std::mt19937 rng(seed);
    const SampledLikelihood s = sampledLikelihood(toy.factors, toy.values, toy.marginal, 200, rng);
    const double relativeError = std::exp(truth - s.logLikelihood) - 1.0;  // (truth − mean) / mean
    if (std::abs(relativeError) > 1.96 * s.relativeStandardError) ++outside;
  }
  EXPECT_LE(outside, 20);
}

TEST(SampledLikelihood, SampleWeightMultipliesTheIntegrand) {
  // w(X) = 1 on half the space (a > its mean along x): with a symmetric integrand about the mean, the weighted
  // likelihood of a measurement at the mean is half the unweighted one.
  LinearToy toy;
  toy.measure(toy.values.at<Point2>(toy.a), toy.values.at<Point2>(toy.b));
  const double meanX = toy.za.x();
  std::mt19937 rng(3);
  const SampledLikelihood half = sampledLikelihood(toy.factors, toy.values, toy.marginal, 40000, rng,
                                                   [&](const Values& s) { return s.at<Point2>(toy.a).x() > meanX ? 1.0 : 0.0; });
  EXPECT_NEAR(half.logLikelihood, toy.closedForm() + std::log(0.5), 0.03);
}

TEST(SampledLikelihood, SharedDrawsOfTheWholeMarginalServeAFactorSetOnPartOfIt) {
  // The draws of (a, b) are draws of a's marginal: a's factor alone, weighed on them, is its closed form.
  const LinearToy toy;
  std::mt19937 rng(7);
  const MarginalSamples draws(toy.values, toy.marginal, 20000, rng);
  const std::vector<FactorPtr> onlyA = {toy.factors[0]};
  const SampledLikelihood a = sampledLikelihood(onlyA, draws);
  EXPECT_NEAR(a.logLikelihood, linearizedLikelihood(onlyA, toy.values, toy.marginal).logLikelihood,
              4.0 * a.relativeStandardError);
  const SampledLikelihood both = sampledLikelihood(toy.factors, draws);
  EXPECT_NEAR(both.logLikelihood, toy.closedForm(), 4.0 * both.relativeStandardError);
  // Fresh draws from the same seed are the same draws: the one-call form is the shared form.
  std::mt19937 again(7);
  EXPECT_EQ(sampledLikelihood(toy.factors, toy.values, toy.marginal, 20000, again).logLikelihood, both.logLikelihood);
  // A factor on a variable the draws do not hold is refused.
  std::mt19937 other(1);
  const JointMarginal onlyAMarginal({toy.a}, {2}, toy.covariance.topLeftCorner(2, 2));
  EXPECT_THROW(sampledLikelihood(toy.factors, MarginalSamples(toy.values, onlyAMarginal, 10, other)),
               std::invalid_argument);
}

TEST(SampledLikelihood, LogTermsOfFactorSetsOnSharedDrawsAdd) {
  // The per-draw log integrand of a union of factor sets is the sum of theirs (hybrid/PropWeights.cpp weighs each
  // candidate as such a sum), and the likelihood is the log-space mean of the terms.
  const LinearToy toy;
  std::mt19937 rng(11);
  const MarginalSamples draws(toy.values, toy.marginal, 500, rng);
  const std::vector<FactorPtr> first = {toy.factors[0]}, second = {toy.factors[1]};
  const Vector sum = sampledLogTerms(first, draws) + sampledLogTerms(second, draws);
  const Vector whole = sampledLogTerms(toy.factors, draws);
  ASSERT_EQ(whole.size(), 500);
  EXPECT_LT((whole - sum).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + whole.cwiseAbs().maxCoeff()));
  const SampledLikelihood likelihood = sampledLikelihood(toy.factors, draws);
  const double maximum = whole.maxCoeff();
  EXPECT_NEAR(likelihood.logLikelihood, maximum + std::log((whole.array() - maximum).exp().mean()), 1e-12);
  // A weight of zero at a draw is a term of −∞ there.
  const Vector weighted = sampledLogTerms(first, draws, [](const Values&) { return 0.0; });
  EXPECT_TRUE((weighted.array() == -std::numeric_limits<double>::infinity()).all());
}

TEST(SampledLikelihood, SharedDrawsMakeTheRatioOfTwoCandidatesLessNoisy) {
  // Two candidates that explain a measurement by the same variable at nearby values (as two associations of one
  // hybrid component share x_k): over 300 seeds, the log-ratio of their estimates varies less on shared draws.
  const LinearToy toy;
  const auto priorOnA = [&](const Vector2& z) -> std::vector<FactorPtr> {
    return {std::make_shared<const PriorFactor<Point2>>(toy.a, Point2(z), NoiseModel::fromCovariance(toy.Ra))};
  };
  const std::vector<FactorPtr> first = priorOnA(toy.za), second = priorOnA(toy.za + Vector2(0.2, 0.1));
  double sharedSum = 0, sharedSquares = 0, freshSum = 0, freshSquares = 0;
  const int seeds = 300;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    const MarginalSamples draws(toy.values, toy.marginal, 100, rng);
    const double shared = sampledLikelihood(first, draws).logLikelihood - sampledLikelihood(second, draws).logLikelihood;
    const double fresh = sampledLikelihood(first, MarginalSamples(toy.values, toy.marginal, 100, rng)).logLikelihood -
                         sampledLikelihood(second, MarginalSamples(toy.values, toy.marginal, 100, rng)).logLikelihood;
    sharedSum += shared;
    sharedSquares += shared * shared;
    freshSum += fresh;
    freshSquares += fresh * fresh;
  }
  const double sharedVariance = sharedSquares / seeds - std::pow(sharedSum / seeds, 2);
  const double freshVariance = freshSquares / seeds - std::pow(freshSum / seeds, 2);
  EXPECT_LT(sharedVariance, 0.25 * freshVariance) << sharedVariance << " against " << freshVariance;
  // Both estimate the same ratio (its closed form) within their Monte Carlo error.
  const double closedForm = linearizedLikelihood(first, toy.values, toy.marginal).logLikelihood -
                            linearizedLikelihood(second, toy.values, toy.marginal).logLikelihood;
  EXPECT_NEAR(sharedSum / seeds, closedForm, 4.0 * std::sqrt(sharedVariance / seeds) + 0.01);
}

TEST(MarginalLikelihood, SameSeedSameResult) {
  const LinearToy toy;
  std::mt19937 first(5), second(5);
  EXPECT_EQ(sampledLikelihood(toy.factors, toy.values, toy.marginal, 100, first).logLikelihood,
            sampledLikelihood(toy.factors, toy.values, toy.marginal, 100, second).logLikelihood);
}

TEST(MarginalLikelihood, RejectsVariablesMissingFromTheMarginalAndRobustFactors) {
  const LinearToy toy;
  const JointMarginal onlyA({toy.a}, {2}, toy.covariance.topLeftCorner(2, 2));
  EXPECT_THROW(linearizedLikelihood(toy.factors, toy.values, onlyA), std::invalid_argument);
  const std::vector<FactorPtr> robust = {std::make_shared<const PriorFactor<Point2>>(
      toy.a, toy.za, NoiseModel::isotropic(2, 1.0)->withRobustKernel(std::make_shared<HuberKernel>(1.0)))};
  EXPECT_THROW(linearizedLikelihood(robust, toy.values, toy.marginal), std::invalid_argument);
  std::mt19937 rng(1);
  EXPECT_THROW(sampledLikelihood(toy.factors, toy.values, toy.marginal, 1, rng), std::invalid_argument);
}
