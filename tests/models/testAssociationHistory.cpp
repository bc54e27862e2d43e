// AssociationHistory (models/AssociationHistory.h): a persistent list of per-step associations. Equality is by
// contents whichever nodes hold them, extending shares the past, the interner makes equal histories the same
// nodes, a very long history is destroyed without recursing once per step, and the association marginal (A,
// eq. 8) groups equal histories built apart.

#include <gtest/gtest.h>

#include <sstream>

#include "semslam/models/AssociationHistory.h"
#include "semslam/models/HypothesisComponent.h"

namespace semslam {
namespace {

TEST(AssociationHistory, StepsRoundTripAndExtendingSharesThePast) {
  const AssociationHistory empty;
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(empty.size(), 0u);
  EXPECT_TRUE(empty.steps().empty());

  const AssociationHistory past{{1, 2}, {}, {3}};
  EXPECT_EQ(past.size(), 3u);
  EXPECT_EQ(past.steps(), (std::vector<std::vector<int>>{{1, 2}, {}, {3}}));
  EXPECT_EQ(past.back(), std::vector<int>{3});
  const AssociationHistory a = past.extended({4}), b = past.extended({-1});
  EXPECT_TRUE(a.parent().sharesNodesWith(past));
  EXPECT_TRUE(b.parent().sharesNodesWith(past));
  EXPECT_EQ(a.steps(), (std::vector<std::vector<int>>{{1, 2}, {}, {3}, {4}}));
  EXPECT_EQ(past.size(), 3u);  // immutable: extending made new histories
  std::ostringstream text;
  text << a;
  EXPECT_EQ(text.str(), "{{1, 2}, {}, {3}, {4}}");
}

TEST(AssociationHistory, EqualityIsByContentsWhicheverNodesHoldThem) {
  const AssociationHistory a{{1, 2}, {3}}, b{{1, 2}, {3}};
  EXPECT_FALSE(a.sharesNodesWith(b));
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.hash(), b.hash());
  EXPECT_NE(a, (AssociationHistory{{1, 2}, {4}}));
  EXPECT_NE(a, (AssociationHistory{{2, 1}, {3}}));  // same last step, different past
  EXPECT_NE(a, (AssociationHistory{{1, 2}, {3}, {}}));  // a step without detections is still a step
  EXPECT_NE(AssociationHistory{{1}}, (AssociationHistory{{}, {1}}));
  EXPECT_EQ(AssociationHistory(std::vector<std::vector<int>>{{1, 2}, {3}}), a);
}

TEST(AssociationHistory, TheInternerMakesEqualExtensionsTheSameNodes) {
  HistoryInterner step1;
  const AssociationHistory root;
  const AssociationHistory x = step1.extend(root, {1}), y = step1.extend(root, {1}), z = step1.extend(root, {2});
  EXPECT_TRUE(x.sharesNodesWith(y));
  EXPECT_FALSE(x.sharesNodesWith(z));
  HistoryInterner step2;
  const AssociationHistory xa = step2.extend(x, {5}), ya = step2.extend(y, {5}), za = step2.extend(z, {5});
  EXPECT_TRUE(xa.sharesNodesWith(ya));
  EXPECT_NE(xa, za);
  // Equal parents made apart (not by one interner) still give equal extensions.
  const AssociationHistory apart = step2.extend(AssociationHistory{{1}}, {5});
  EXPECT_EQ(apart, xa);
  EXPECT_TRUE(apart.sharesNodesWith(xa));
}

TEST(AssociationHistory, AMillionStepHistoryIsDestroyedWithoutDeepRecursion) {
  // A recursive destructor would need ~10^6 nested frames (far beyond an 8 MB stack).
  AssociationHistory history;
  for (int k = 0; k < 1000000; ++k) history = history.extended({k % 7});
  EXPECT_EQ(history.size(), 1000000u);
  const AssociationHistory shorter = history.parent();
  history = AssociationHistory();  // the last node dies alone; the rest is still held by `shorter`
  EXPECT_EQ(shorter.size(), 999999u);
  EXPECT_EQ(shorter.back(), std::vector<int>{999998 % 7});
}

TEST(AssociationHistory, TheAssociationMarginalGroupsEqualHistoriesBuiltApart) {
  std::vector<HypothesisComponent> components(4);
  components[0].weight = 0.125;  // dyadic weights: the tie below is exact
  components[0].associations = {{1}, {2}};
  components[1].weight = 0.375;
  components[1].associations = {{2}, {1}};
  components[2].weight = 0.25;
  components[2].associations = {{1}, {2}};  // equal to component 0, other nodes
  components[3].weight = 0.25;
  components[3].associations = AssociationHistory{{1}}.extended({3});
  const std::vector<AssociationHypothesis> marginal = associationMarginal(components);
  ASSERT_EQ(marginal.size(), 3u);
  EXPECT_EQ(marginal[0].associations, (AssociationHistory{{1}, {2}}));
  EXPECT_EQ(marginal[0].weight, 0.375);
  EXPECT_EQ(marginal[0].firstComponent, 0u);
  EXPECT_EQ(marginal[1].firstComponent, 1u);  // a tie: the history of the earlier first component first
  EXPECT_EQ(marginal[1].weight, 0.375);
  EXPECT_EQ(marginal[2].firstComponent, 3u);
  EXPECT_EQ(marginal[2].weight, 0.25);
}

}  // namespace
}  // namespace semslam
