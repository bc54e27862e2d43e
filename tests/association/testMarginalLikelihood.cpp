// The one component likelihood of both papers (association/MarginalLikelihood.h): exact on a linear-Gaussian
// problem, the Monte Carlo version within its own standard error, and the innovation chi2 the gate uses.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "semslam/association/MarginalLikelihood.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/graph/NoiseModel.h"

using namespace semslam;

namespace {

double logGaussian(const Vector& x, const Vector& mean, const Matrix& covariance) {
  const Eigen::LLT<Matrix> llt(covariance);
  const Vector whitened = llt.matrixL().solve(x - mean);
  const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  return -0.5 * whitened.squaredNorm() - 0.5 * logDet - 0.5 * x.size() * std::log(2.0 * std::numbers::pi);
}

/// Two point variables with correlated Gaussian beliefs, each measured directly (linear, h = identity).
struct LinearToy {
  Key a = landmarkKey(0), b = landmarkKey(1);
  Values values;
  Matrix covariance = Matrix(4, 4);
  Vector2 za = Vector2(1.3, -0.4), zb = Vector2(2.2, 0.9);
  Matrix Ra = Vector2(0.3, 0.2).asDiagonal(), Rb = (Matrix(2, 2) << 0.5, 0.1, 0.1, 0.4).finished();
  std::vector<FactorPtr> factors;
  JointMarginal marginal;

  LinearToy() {
    values.insert(a, Point2(1.0, -0.5));
    values.insert(b, Point2(2.0, 1.2));
    covariance << 0.20, 0.05, 0.08, 0.00,  //
        0.05, 0.30, 0.02, 0.06,            //
        0.08, 0.02, 0.25, -0.04,           //
        0.00, 0.06, -0.04, 0.15;
    factors = {std::make_shared<const PriorFactor<Point2>>(a, za, NoiseModel::fromCovariance(Ra)),
               std::make_shared<const PriorFactor<Point2>>(b, zb, NoiseModel::fromCovariance(Rb))};
    marginal = JointMarginal({a, b}, {2, 2}, covariance);
  }

  /// The closed form: [za; zb] ~ N([ā; b̄], Σ + blockdiag(Ra, Rb)).
  double closedForm() const {
    Vector z(4), mean(4);
    z << za, zb;
    mean << values.at<Point2>(a), values.at<Point2>(b);
    Matrix S = covariance;
    S.topLeftCorner(2, 2) += Ra;
    S.bottomRightCorner(2, 2) += Rb;
    return logGaussian(z, mean, S);
  }
};

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
  // Over 200 seeds with 200 samples each, |error| / standard error must behave like |N(0, 1)|: at most ~5 % above
  // 1.96 (allowing for binomial noise: ≤ 12 of 200).
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
  toy.za = toy.values.at<Point2>(toy.a);
  toy.zb = toy.values.at<Point2>(toy.b);
  toy.factors = {std::make_shared<const PriorFactor<Point2>>(toy.a, toy.za, NoiseModel::fromCovariance(toy.Ra)),
                 std::make_shared<const PriorFactor<Point2>>(toy.b, toy.zb, NoiseModel::fromCovariance(toy.Rb))};
  const double meanX = toy.za.x();
  std::mt19937 rng(3);
  const SampledLikelihood half = sampledLikelihood(toy.factors, toy.values, toy.marginal, 40000, rng,
                                                   [&](const Values& s) { return s.at<Point2>(toy.a).x() > meanX ? 1.0 : 0.0; });
  EXPECT_NEAR(half.logLikelihood, toy.closedForm() + std::log(0.5), 0.03);
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
