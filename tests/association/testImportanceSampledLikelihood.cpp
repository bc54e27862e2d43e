// Importance sampling of the marginal likelihood from the linearised posterior
// (association/ImportanceSampledLikelihood.h): exact with zero variance on a linear-Gaussian problem, and on a
// nonlinear range-bearing measurement under a broad prior far less variable than plain Monte Carlo (A, eq. 17).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <numbers>
#include <random>

#include "semslam/association/ImportanceSampledLikelihood.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/graph/NoiseModel.h"
#include "association/LinearToy.h"

using namespace semslam;
using semslam::test::LinearToy;

namespace {

/// A range-bearing detection of a landmark from a robot whose position prior is broad (σ = 10 m, as the
/// aliased2d default's initial prior), the robot truly 4 m from its prior mean.
struct BroadRangeBearing {
  Key x = poseKey(0), l = landmarkKey(0);
  Values values;
  std::vector<FactorPtr> factors;
  JointMarginal marginal;

  BroadRangeBearing() {
    values.insert(x, SE2(0.0, 0.0, 0.0));
    values.insert(l, Point2(6.0, 2.0));
    const SE2 truth(3.0, -2.5, 0.2);
    const Vector2 z = RangeBearingSensor2().predict(truth, Point2(6.2, 1.8));
    factors = {std::make_shared<const RangeBearingFactor<Point2>>(x, l, z, NoiseModel::fromSigmas(Vector2(0.1, 0.02)))};
    Matrix covariance = Matrix::Zero(5, 5);
    covariance.diagonal() << 100.0, 100.0, 0.09, 0.25, 0.25;
    marginal = JointMarginal({x, l}, {3, 2}, covariance);
  }
};

double standardDeviation(const std::vector<double>& v) {
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double sum = 0.0;
  for (double x : v) sum += (x - mean) * (x - mean);
  return std::sqrt(sum / static_cast<double>(v.size() - 1));
}

}  // namespace

TEST(ImportanceSampledLikelihood, IsExactWithEqualWeightsOnALinearGaussianProblem) {
  const LinearToy toy;
  std::mt19937 rng(7);
  const SampledLikelihood result = importanceSampledLikelihood(toy.factors, toy.values, toy.marginal, 50, rng);
  EXPECT_EQ(result.samples, 50);
  EXPECT_NEAR(result.logLikelihood, toy.closedForm(), 1e-10);
  EXPECT_LT(result.relativeStandardError, 1e-10);  // every weight is p(z)
}

TEST(ImportanceSampledLikelihood, AgreesWithPlainMonteCarloOnANonlinearMeasurement) {
  // Under a moderate prior plain sampling is accurate; both estimate the same integral.
  BroadRangeBearing problem;
  Matrix covariance = Matrix::Zero(5, 5);
  covariance.diagonal() << 1.0, 1.0, 0.04, 0.25, 0.25;
  problem.marginal = JointMarginal({problem.x, problem.l}, {3, 2}, covariance);
  problem.values.update(problem.x, SE2(2.5, -2.0, 0.15));
  std::mt19937 first(1), second(2);
  const SampledLikelihood plain = sampledLikelihood(problem.factors, problem.values, problem.marginal, 200000, first);
  const SampledLikelihood importance =
      importanceSampledLikelihood(problem.factors, problem.values, problem.marginal, 20000, second);
  const double tolerance = 4.0 * std::hypot(plain.relativeStandardError, importance.relativeStandardError);
  EXPECT_LT(plain.relativeStandardError, 0.05);
  EXPECT_NEAR(importance.logLikelihood, plain.logLikelihood, tolerance);
}

TEST(ImportanceSampledLikelihood, VariesFarLessThanPlainMonteCarloUnderABroadPrior) {
  // 40 seeds, 1000 samples each: the spread over seeds of the log estimate must be far smaller with the
  // linearised-posterior proposal than with plain sampling from the prior. Measured (printed): sd of log 0.74 vs
  // 12. Not asserted, and documented in docs/hybrid-belief.md: under this σ = 10 m prior the importance weights
  // are heavy-tailed (the Gaussian proposal does not cover all of the curved posterior), so even 400000
  // importance samples sit ≈ e⁻¹ below a 2·10⁶-sample plain estimate (rse 0.05): lower variance, not no bias.
  const BroadRangeBearing problem;
  std::vector<double> plainLogs, importanceLogs;
  for (unsigned seed = 0; seed < 40; ++seed) {
    std::mt19937 a(seed), b(seed);
    plainLogs.push_back(sampledLikelihood(problem.factors, problem.values, problem.marginal, 1000, a).logLikelihood);
    importanceLogs.push_back(
        importanceSampledLikelihood(problem.factors, problem.values, problem.marginal, 1000, b).logLikelihood);
  }
  std::printf("sd over 40 seeds of the log estimate, n = 1000: plain %.3g, importance %.3g\n",
              standardDeviation(plainLogs), standardDeviation(importanceLogs));
  EXPECT_LT(standardDeviation(importanceLogs), 0.2 * standardDeviation(plainLogs));
}

TEST(ImportanceSampledLikelihood, IteratedProposalIsExactOnALinearProblemToo) {
  const LinearToy toy;
  std::mt19937 rng(9);
  const SampledLikelihood result =
      importanceSampledLikelihood(toy.factors, toy.values, toy.marginal, 20, rng, {}, ImportanceProposal{5});
  EXPECT_NEAR(result.logLikelihood, toy.closedForm(), 1e-10);
  EXPECT_LT(result.relativeStandardError, 1e-10);
  EXPECT_THROW(importanceSampledLikelihood(toy.factors, toy.values, toy.marginal, 20, rng, {}, ImportanceProposal{0}),
               std::invalid_argument);
}

TEST(ImportanceSampledLikelihood, SampleWeightMultipliesTheIntegrandAndSameSeedSameResult) {
  LinearToy toy;
  toy.measure(toy.values.at<Point2>(toy.a), toy.values.at<Point2>(toy.b));
  const double meanX = toy.za.x();
  const SampleWeight half = [&](const Values& s) { return s.at<Point2>(toy.a).x() > meanX ? 1.0 : 0.0; };
  std::mt19937 rng(3), again(3);
  const SampledLikelihood weighted = importanceSampledLikelihood(toy.factors, toy.values, toy.marginal, 40000, rng, half);
  EXPECT_NEAR(weighted.logLikelihood, toy.closedForm() + std::log(0.5), 0.03);
  EXPECT_EQ(weighted.logLikelihood,
            importanceSampledLikelihood(toy.factors, toy.values, toy.marginal, 40000, again, half).logLikelihood);
}

TEST(ImportanceSampledLikelihood, RejectsTooFewSamplesAndASingularPrior) {
  const LinearToy toy;
  std::mt19937 rng(1);
  EXPECT_THROW(importanceSampledLikelihood(toy.factors, toy.values, toy.marginal, 1, rng), std::invalid_argument);
  const JointMarginal singular({toy.a, toy.b}, {2, 2}, Matrix::Zero(4, 4));
  EXPECT_THROW(importanceSampledLikelihood(toy.factors, toy.values, singular, 10, rng), std::invalid_argument);
}
