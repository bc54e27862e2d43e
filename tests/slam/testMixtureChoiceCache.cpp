// MixtureChoiceCache (docs/association-front-end.md §6b, "The reach of a choice"): its every answer is the mixture's
// activeComponent at the estimate asked about, while most answers reuse an earlier choice.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "semslam/factors/MaxMixtureFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/factors/RelativePointFactor.h"
#include "semslam/graph/NoiseModel.h"
#include "semslam/slam/MixtureChoiceCache.h"

namespace semslam {
namespace {

const Key kRobot = poseKey(0);
const Key kLandmark = landmarkKey(0);
const Key kOther = landmarkKey(1);

/// Paper B's mixture of a detection: its candidate's factor and the same widened by 100, the null hypothesis.
FactorPtr mixtureOf(const std::function<FactorPtr(double)>& factor) {
  return std::make_shared<const MaxMixtureFactor>(std::vector<MaxMixtureFactor::Component>{
      {factor(1.0), 0.9}, {factor(100.0), 0.1, MaxMixtureFactor::Widening{0, 100.0}}});
}

TEST(MixtureChoiceCache, AnswersAsActiveComponentWhileTheEstimateWandersAcrossTheNullsSwitch) {
  // A 2D range-bearing and a 2D relative-position detection of one landmark, asked at every step while the
  // landmark's estimate slides 1 m sideways and back (twice, past the null's switch at about 0.5 m) and the robot
  // and landmark jitter about that path by amounts from micrometres to decimetres. Every answer must be
  // activeComponent's; a cache that kept a choice beyond its reach would answer the old component after a switch.
  const FactorPtr rangeBearing = mixtureOf([](double s) -> FactorPtr {
    return std::make_shared<const RangeBearingFactor<Point2>>(kRobot, kLandmark, Vector2(5.0, 0.2),
                                                              NoiseModel::fromSigmas(Vector2(0.1, 0.02) * s));
  });
  const FactorPtr relative = mixtureOf([](double s) -> FactorPtr {
    return std::make_shared<const RelativePointFactor<SE2, Point2>>(kRobot, kLandmark, Point2(4.9, 1.0),
                                                                    NoiseModel::fromSigmas(Vector2(0.1, 0.1) * s));
  });
  std::mt19937 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> exponent(-6.0, -1.0);
  MixtureChoiceCache cache;
  Values estimate;
  estimate.insert(kRobot, SE2(0.0, 0.0, 0.0));
  estimate.insert(kLandmark, Point2(4.9, 1.0));
  int asked = 0;
  std::vector<int> seen(2, 0);
  for (int step = 0; step < 2000; ++step) {
    const double size = std::pow(10.0, exponent(rng));
    const double slide = 1.0 - std::abs(1.0 - (step % 1000) / 500.0);  // 0 → 1 → 0 m over 1000 steps
    estimate.update(kRobot, SE2().retract(Vector3(normal(rng), normal(rng), 0.1 * normal(rng)) * size));
    estimate.update(kLandmark, Point2(Point2(4.9, 1.0 + slide) + Point2(normal(rng), normal(rng)) * size));
    for (const auto& [detection, mixture] : {std::pair{0, rangeBearing}, std::pair{1, relative}}) {
      const int expected = mixture->activeComponent(estimate);
      ASSERT_EQ(cache.activeComponent(static_cast<std::size_t>(detection), mixture, estimate), expected)
          << "step " << step << ", detection " << detection;
      ++seen[static_cast<std::size_t>(expected)];
      ++asked;
    }
  }
  EXPECT_GT(seen[0], 1000);  // both components are the answer often: the slide crosses the switch
  EXPECT_GT(seen[1], 1000);
  EXPECT_LT(cache.choicesMade(), asked / 2);  // and most answers reuse a choice
}

TEST(MixtureChoiceCache, ChoosesAnewForAReplacedMixtureOrOneOverTwoLandmarks) {
  const auto factor = [](Key landmark, double s) -> FactorPtr {
    return std::make_shared<const RangeBearingFactor<Point2>>(kRobot, landmark, Vector2(5.0, 0.0),
                                                              NoiseModel::fromSigmas(Vector2(0.1, 0.02) * s));
  };
  Values estimate;
  estimate.insert(kRobot, SE2());
  estimate.insert(kLandmark, Point2(5.0, 0.0));
  estimate.insert(kOther, Point2(5.0, 1.0));
  MixtureChoiceCache cache;
  const FactorPtr first = mixtureOf([&](double s) { return factor(kLandmark, s); });
  EXPECT_EQ(cache.activeComponent(0, first, estimate), 0);
  EXPECT_EQ(cache.activeComponent(0, first, estimate), 0);
  EXPECT_EQ(cache.choicesMade(), 1u);
  // The detection's mixture replaced by one on the other landmark (far off: the null wins): chosen anew.
  const FactorPtr second = mixtureOf([&](double s) { return factor(kOther, s); });
  EXPECT_EQ(cache.activeComponent(0, second, estimate), 1);
  EXPECT_EQ(cache.choicesMade(), 2u);
  // Components on two landmarks have no reach: every answer is a choice.
  const FactorPtr both = std::make_shared<const MaxMixtureFactor>(
      std::vector<MaxMixtureFactor::Component>{{factor(kLandmark, 1.0), 0.5}, {factor(kOther, 1.0), 0.5}});
  EXPECT_EQ(cache.activeComponent(1, both, estimate), 0);
  EXPECT_EQ(cache.activeComponent(1, both, estimate), 0);
  EXPECT_EQ(cache.choicesMade(), 4u);
}

}  // namespace
}  // namespace semslam
