// The M-of-N rule of provisional landmarks (docs/association-front-end.md §5).
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "semslam/association/LandmarkLifecycle.h"

using namespace semslam;
using State = LandmarkLifecycle::State;

TEST(LandmarkLifecycle, ConfirmsOnlyWithDetectionsSpacedAtLeastDeltaT) {
  LandmarkLifecycle lifecycle = LandmarkLifecycle({2, 3.0, 10});  // Δt = 3 s
  const int j = lifecycle.addProvisional(10.0);
  EXPECT_TRUE(lifecycle.provisional(j));
  EXPECT_FALSE(lifecycle.observe(j, 11.0));  // a burst: too soon, not counted
  EXPECT_FALSE(lifecycle.observe(j, 12.0));
  EXPECT_TRUE(lifecycle.provisional(j));
  EXPECT_TRUE(lifecycle.observe(j, 13.0));  // exactly Δt after the birth
  EXPECT_EQ(lifecycle.state(j), State::Confirmed);
  EXPECT_FALSE(lifecycle.observe(j, 20.0));  // already confirmed: nothing to decide
}

TEST(LandmarkLifecycle, WithAViewpointDistanceASightingFromTheSamePlaceDoesNotCount) {
  // An observer standing still sees another robot standing still: the same view again and again, whose errors are
  // the same, not a second sighting of a static object (§5, --confirmation-viewpoint).
  LandmarkLifecycle::Rule rule{2, 1.0, 10};
  rule.viewpointDistance = 0.5;
  LandmarkLifecycle lifecycle = LandmarkLifecycle(rule);  // Δt = 1 s
  const int j = lifecycle.addProvisional(0.0, Vector2(1.0, 1.0));
  EXPECT_FALSE(lifecycle.observe(j, 1.0, Vector2(1.0, 1.0)));   // spaced in time, from the same place
  EXPECT_FALSE(lifecycle.observe(j, 5.0, Vector2(1.3, 1.3)));   // 0.42 m away: still the same view
  EXPECT_TRUE(lifecycle.provisional(j));
  EXPECT_TRUE(lifecycle.observe(j, 6.0, Vector2(1.0, 1.5)));    // 0.5 m from the birth's view
  // Off (0, the default): only the time spacing counts.
  LandmarkLifecycle timeOnly = LandmarkLifecycle({2, 1.0, 10});
  const int k = timeOnly.addProvisional(0.0, Vector2(1.0, 1.0));
  EXPECT_TRUE(timeOnly.observe(k, 1.0, Vector2(1.0, 1.0)));
}

TEST(LandmarkLifecycle, AViewpointInSigmasScalesWithTheSightingsOwnPositionError) {
  // D = max(viewpointDistance, viewpointSigmas × σ_p): a sighting counts once the robot has moved by more than
  // k position errors of that sighting (§5, --confirmation-viewpoint-sigmas).
  LandmarkLifecycle::Rule rule{2, 1.0, 10};
  rule.viewpointSigmas = 2.0;
  LandmarkLifecycle lifecycle = LandmarkLifecycle(rule);
  const int j = lifecycle.addProvisional(0.0, Vector2(0.0, 0.0));
  EXPECT_FALSE(lifecycle.observe(j, 1.0, Vector2(0.3, 0.0), 0.2));  // 0.3 m < 2 × 0.2 m
  EXPECT_TRUE(lifecycle.provisional(j));
  EXPECT_TRUE(lifecycle.observe(j, 2.0, Vector2(0.3, 0.0), 0.1));   // the same move, a sharper sighting: 0.3 ≥ 0.2
  // With both set, the larger distance applies.
  rule.viewpointDistance = 0.5;
  LandmarkLifecycle both = LandmarkLifecycle(rule);
  const int k = both.addProvisional(0.0, Vector2(0.0, 0.0));
  EXPECT_FALSE(both.observe(k, 1.0, Vector2(0.3, 0.0), 0.1));  // 0.3 m < max(0.5, 0.2)
  EXPECT_FALSE(both.observe(k, 2.0, Vector2(0.6, 0.0), 0.4));  // 0.6 m < max(0.5, 0.8)
  EXPECT_TRUE(both.observe(k, 3.0, Vector2(0.6, 0.0), 0.2));   // 0.6 m ≥ max(0.5, 0.4)
  // Refused: a negative or non-finite distance.
  LandmarkLifecycle::Rule negative{2, 1.0, 10};
  negative.viewpointSigmas = -1.0;
  EXPECT_THROW(LandmarkLifecycle{negative}, std::invalid_argument);
  LandmarkLifecycle::Rule infinite{2, 1.0, 10};
  infinite.viewpointDistance = std::numeric_limits<double>::infinity();
  EXPECT_THROW(LandmarkLifecycle{infinite}, std::invalid_argument);
}

TEST(LandmarkLifecycle, ThreeConfirmationsCountFromTheLastCountedDetection) {
  LandmarkLifecycle lifecycle = LandmarkLifecycle({3, 2.0, 10});  // Δt = 2 s
  const int j = lifecycle.addProvisional(0.0);
  EXPECT_FALSE(lifecycle.observe(j, 2.0));  // counted: 2 of 3
  EXPECT_FALSE(lifecycle.observe(j, 3.0));  // 1 s after the last counted: not counted
  EXPECT_TRUE(lifecycle.observe(j, 4.0));
}

TEST(LandmarkLifecycle, DropsAfterPatienceInFieldSteps) {
  LandmarkLifecycle lifecycle = LandmarkLifecycle({2, 3.0, 4});
  const int j = lifecycle.addProvisional(0.0);
  EXPECT_FALSE(lifecycle.passedInField(j));
  EXPECT_FALSE(lifecycle.passedInField(j));
  EXPECT_FALSE(lifecycle.passedInField(j));
  EXPECT_TRUE(lifecycle.passedInField(j));
  lifecycle.drop(j);
  EXPECT_EQ(lifecycle.state(j), State::Dropped);
  EXPECT_FALSE(lifecycle.active(j));
  EXPECT_THROW(lifecycle.drop(j), std::logic_error);
}

TEST(LandmarkLifecycle, MergesFollowChains) {
  LandmarkLifecycle lifecycle;
  const int mapped = lifecycle.addConfirmed();
  const int a = lifecycle.addProvisional(0.0);
  const int b = lifecycle.addProvisional(0.0);
  lifecycle.merge(b, a);
  lifecycle.merge(a, mapped);
  EXPECT_EQ(lifecycle.mergedInto(b), mapped);
  EXPECT_EQ(lifecycle.mergedInto(a), mapped);
  EXPECT_EQ(lifecycle.mergedInto(mapped), std::nullopt);
  EXPECT_THROW(lifecycle.merge(mapped, a), std::logic_error);  // into a merged landmark
  EXPECT_THROW(lifecycle.merge(a, mapped), std::logic_error);  // a merged landmark again
  EXPECT_THROW(lifecycle.merge(mapped, mapped), std::logic_error);
}

TEST(LandmarkLifecycle, AConfirmedDuplicateMergesIntoAnotherConfirmedLandmark) {
  LandmarkLifecycle lifecycle;
  const int older = lifecycle.addConfirmed();
  const int newer = lifecycle.addConfirmed();
  lifecycle.merge(newer, older);
  EXPECT_EQ(lifecycle.state(newer), State::Merged);
  EXPECT_FALSE(lifecycle.active(newer));
  EXPECT_EQ(lifecycle.mergedInto(newer), older);
  EXPECT_FALSE(lifecycle.observe(newer, 10.0));  // a merged landmark counts nothing
}

TEST(LandmarkLifecycle, OneConfirmationMeansEveryBirthIsConfirmed) {
  LandmarkLifecycle lifecycle({1, 3.0, 10});
  EXPECT_EQ(lifecycle.state(lifecycle.addProvisional(0.0)), State::Confirmed);
  EXPECT_THROW(LandmarkLifecycle({0, 3.0, 10}), std::invalid_argument);
  EXPECT_THROW(LandmarkLifecycle({2, -1.0, 10}), std::invalid_argument);
  EXPECT_THROW(LandmarkLifecycle({2, 3.0, 0}), std::invalid_argument);
}
