// Generated aliased2d layouts (sim/Aliased2dLayout.h): seeded and byte-stable, the rule holds on every seed tried,
// and the geometry of a pair is exactly that of every other pair, translated.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>

#include "semslam/io/ScenarioFile.h"
#include "semslam/models/AnalyticViewpointClassifier.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/Viewpoint.h"
#include "semslam/sim/Aliased2dLayout.h"
#include "SimTesting.h"

namespace semslam {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Aliased2dLayout, ASeedGivesTheSameLayoutAndTheCheckedInFileByteForByte) {
  EXPECT_TRUE(generatedAliased2dScenario(1) == generatedAliased2dScenario(1));
  EXPECT_FALSE(generateAliased2dLayout(1) == generateAliased2dLayout(2));
  // The file pins the numbers: a change of stream, draw order or rule shows here.
  EXPECT_EQ(aliased2dScenarioToJson(generatedAliased2dScenario(1)),
            test::fileBytes(std::string(SEMSLAM_SOURCE_DIR) + "/data/scenarios/aliased2d_layout_1.json"));
}

TEST(Aliased2dLayout, EverySeedKeepsTheRule) {
  const Aliased2dLayoutRule rule;
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    const std::vector<Aliased2dObject> objects = generateAliased2dLayout(seed, rule);
    ASSERT_EQ(objects.size(), 6u) << "seed " << seed;
    const Point2 offset = objects[1].pose.translation() - objects[0].pose.translation();
    EXPECT_GE(offset.norm(), rule.pairOffsetMin - 1e-12);
    EXPECT_LE(offset.norm(), rule.pairOffsetMax + 1e-12);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const Aliased2dObject& object = objects[i];
      EXPECT_EQ(object.id, static_cast<int>(i));
      EXPECT_EQ(object.classIndex, 0);
      const Point2 p = object.pose.translation();
      EXPECT_TRUE((p.array() >= rule.boxMin.array()).all() && (p.array() <= rule.boxMax.array()).all())
          << "seed " << seed << " object " << i << " outside the box";
      EXPECT_GE(object.pose.theta(), -kPi);
      EXPECT_LE(object.pose.theta(), kPi);
      if (i % 2 == 1) {  // every pair is the same offset: a translated copy of pair 0
        EXPECT_LT((p - objects[i - 1].pose.translation() - offset).norm(), 1e-12);
      }
      for (std::size_t j = 0; j < i; ++j) {
        const double distance = (p - objects[j].pose.translation()).norm();
        if (j / 2 != i / 2) EXPECT_GE(distance, rule.pairSpacing) << "seed " << seed << " objects " << j << ", " << i;
      }
    }
  }
}

TEST(Aliased2dLayout, APairSeenFromAPoseIsEveryOtherPairSeenFromThePoseTranslated) {
  const Aliased2dScenario scenario = generatedAliased2dScenario(4);
  const RangeBearingSensor2 sensor(scenario.sensor.bodyToSensor);
  const AnalyticViewpointClassifier classifier(scenario.alpha, scenario.sharpness);
  const SE2 robot(1.0, -1.5, 0.4);
  double largestScoreDifference = 0.0;
  for (int pair = 1; pair < 3; ++pair) {
    const Point2 shift = scenario.objects[2 * pair].pose.translation() - scenario.objects[0].pose.translation();
    const SE2 moved(robot.x() + shift.x(), robot.y() + shift.y(), robot.theta());
    for (int member = 0; member < 2; ++member) {
      const Aliased2dObject& original = scenario.objects[member];
      const Aliased2dObject& copy = scenario.objects[2 * pair + member];
      const Vector2 here = sensor.predict(robot, original.pose.translation());
      const Vector2 there = sensor.predict(moved, copy.pose.translation());
      EXPECT_LT((here - there).norm(), 1e-9) << "pair " << pair << " member " << member;
      // The classifier sees each object from its own side: the headings are drawn object by object.
      const Vector scoresHere = classifier.mean(0, viewpointAngle(robot, original.pose));
      const Vector scoresThere = classifier.mean(0, viewpointAngle(moved, copy.pose));
      largestScoreDifference = std::max(largestScoreDifference, (scoresHere - scoresThere).norm());
    }
  }
  EXPECT_GT(largestScoreDifference, 1e-3);
}

TEST(Aliased2dLayout, TheScenarioIsTheDefaultsWithTheLayoutAndItsArena) {
  const Aliased2dScenario generated = generatedAliased2dScenario(9);
  const Aliased2dScenario defaults = defaultAliased2dScenario();
  EXPECT_EQ(generated.name, "aliased2d-layout-9");
  EXPECT_TRUE(generated.priors == defaults.priors);
  EXPECT_TRUE(generated.sensor == defaults.sensor);
  EXPECT_TRUE(generated.start.equals(defaults.start, 0.0));
  EXPECT_EQ(generated.motion.arenaCenter, Point2(7.5, 0.0));
  EXPECT_EQ(generated.motion.arenaRadius, defaults.motion.arenaRadius);
}

TEST(Aliased2dLayout, ARuleThatCannotHoldIsRefused) {
  Aliased2dLayoutRule rule;
  rule.pairs = 0;
  EXPECT_THROW(generateAliased2dLayout(1, rule), std::invalid_argument);
  rule = {};
  rule.pairOffsetMin = 5.0;
  rule.pairOffsetMax = 4.0;
  EXPECT_THROW(generateAliased2dLayout(1, rule), std::invalid_argument);
  rule = {};
  rule.pairSpacing = std::nan("");
  EXPECT_THROW(generateAliased2dLayout(1, rule), std::invalid_argument);
  rule = {};
  rule.pairSpacing = 40.0;  // three pairs 40 m apart do not fit a 15 × 10 m box
  EXPECT_THROW(generateAliased2dLayout(1, rule), std::runtime_error);
}

}  // namespace
}  // namespace semslam
