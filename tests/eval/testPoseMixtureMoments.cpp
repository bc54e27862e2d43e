// The moment-matched Gaussian of an SE(2) mixture (eval/PoseMixtureMoments.h): exact for one component, the weighted
// Karcher mean, and a covariance that matches a Monte Carlo draw of the mixture, which it does only with the
// components' covariances transported by Jr⁻¹(δ_i) (the plain sum misses the heading-to-position coupling).

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "semslam/eval/PoseMixtureMoments.h"
#include "semslam/models/Sampling.h"

namespace semslam {
namespace {

TEST(PoseMixtureMoments, OneComponentIsItself) {
  const SE2 mean(1.0, -2.0, 0.4);
  Matrix3 covariance;
  covariance << 0.04, 0.01, 0.002, 0.01, 0.09, -0.003, 0.002, -0.003, 0.01;
  const PoseGaussian2 matched = momentMatchedPoseMixture({2.5}, {mean}, {covariance});
  EXPECT_TRUE(matched.mean.equals(mean, 1e-14));
  EXPECT_LT((matched.covariance - covariance).norm(), 1e-15);
}

TEST(PoseMixtureMoments, TheMeanIsTheWeightedKarcherMean) {
  const SE2 frame(1.0, 2.0, 0.7);
  const std::vector<SE2> means = {frame.compose(SE2(-1.0, 0.5, -0.3)), frame.compose(SE2(2.0, -1.0, 0.2)),
                                  frame.compose(SE2(0.5, 3.0, 0.4))};
  const std::vector<double> weights = {0.2, 0.5, 0.3};
  const PoseGaussian2 matched = momentMatchedPoseMixture(weights, means, {Matrix3::Identity(), Matrix3::Identity(),
                                                                          Matrix3::Identity()});
  Vector3 weighted = Vector3::Zero();
  for (std::size_t i = 0; i < means.size(); ++i) weighted += weights[i] * SE2::Log(matched.mean.between(means[i]));
  EXPECT_LT(weighted.norm(), 1e-10);
}

TEST(PoseMixtureMoments, TheCovarianceMatchesAMonteCarloDrawOfTheMixture) {
  // Two bays 6 m apart, seen from a rotated frame; heading σ 0.1 rad, which 3 m from the mean moves y by 0.3 m.
  const SE2 frame(1.0, 2.0, 0.7);
  const std::vector<SE2> means = {frame.compose(SE2(-3.0, 0.0, 0.0)), frame.compose(SE2(3.0, 0.0, 0.0))};
  const std::vector<double> weights = {0.5, 0.5};
  const std::vector<Matrix3> covariances = {Vector3(0.01, 0.01, 0.01).asDiagonal(),
                                            Vector3(0.02, 0.005, 0.01).asDiagonal()};
  const PoseGaussian2 matched = momentMatchedPoseMixture(weights, means, covariances);
  EXPECT_TRUE(matched.mean.equals(frame, 1e-9));

  std::mt19937 rng(5);
  const int draws = 400000;
  Matrix3 sampled = Matrix3::Zero();
  Vector3 sampledMean = Vector3::Zero();
  for (int s = 0; s < draws; ++s) {
    const std::size_t i = uniform01(rng) < weights[0] ? 0 : 1;
    const Vector e = sampleGaussian(Vector::Zero(3), covariances[i], rng);
    const Vector3 error = SE2::Log(matched.mean.between(means[i].compose(SE2::Exp(Vector3(e)))));
    sampledMean += error / draws;
    sampled += error * error.transpose() / draws;
  }
  sampled -= sampledMean * sampledMean.transpose();
  EXPECT_LT(sampledMean.norm(), 0.01);
  // Monte Carlo standard error of the yy entry ≈ 0.03 · √(2 / 4e5) ≈ 7e-5; the second-order terms are smaller.
  EXPECT_NEAR(matched.covariance(1, 1), sampled(1, 1), 1e-3);
  EXPECT_NEAR(matched.covariance(2, 2), sampled(2, 2), 1e-3);
  EXPECT_NEAR(matched.covariance(1, 2), sampled(1, 2), 1e-3);
  EXPECT_NEAR(matched.covariance(0, 0), sampled(0, 0), 0.05);  // 9 m² of spread: a larger Monte Carlo error
  // Without the transport the position-heading coupling is missing: yy would be the plain mean 0.0075.
  const double plainYY = 0.5 * (covariances[0](1, 1) + covariances[1](1, 1));
  EXPECT_GT(sampled(1, 1) - plainYY, 0.015);
}

TEST(PoseMixtureMoments, RejectsBadInput) {
  const Matrix3 identity = Matrix3::Identity();
  EXPECT_THROW(momentMatchedPoseMixture({}, {}, {}), std::invalid_argument);
  EXPECT_THROW(momentMatchedPoseMixture({1.0, 1.0}, {SE2()}, {identity}), std::invalid_argument);
  EXPECT_THROW(momentMatchedPoseMixture({-1.0}, {SE2()}, {identity}), std::invalid_argument);
  EXPECT_THROW(momentMatchedPoseMixture({0.0}, {SE2()}, {identity}), std::invalid_argument);
  EXPECT_THROW(momentMatchedPoseMixture({std::nan("")}, {SE2()}, {identity}), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
