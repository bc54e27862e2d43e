// Association errors by kind (AssociationErrors.h): the header's worked examples, each kind of error alone, clutter
// both ways, and invariance under renaming the estimated landmarks.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "semslam/eval/AssociationErrors.h"

namespace semslam {
namespace {

constexpr int kClutter = kNotALandmark;
constexpr int a = 0, b = 1, c = 2;

std::vector<DetectionAssociation> make(const std::vector<std::pair<int, std::optional<int>>>& list) {
  std::vector<DetectionAssociation> out;
  for (const auto& [truth, estimate] : list) out.push_back({truth, estimate});
  return out;
}

AssociationErrors evaluate(const std::vector<DetectionAssociation>& d) {
  return evaluateAssociationErrors(d, matchLandmarks(d));
}

TEST(AssociationErrors, PerfectAssociationHasNoErrorOfAnyKind) {
  const auto e = evaluate(make({{a, 7}, {a, 7}, {b, 3}, {b, 3}, {c, 5}, {kClutter, std::nullopt}}));
  EXPECT_EQ(e.accuracyReal, 1.0);
  EXPECT_EQ(e.pairwisePrecision, 1.0);
  EXPECT_EQ(e.pairwiseRecall, 1.0);
  EXPECT_EQ(e.clutterRejected, 1.0);
  EXPECT_EQ(e.landmarksMerged, 0u);
  EXPECT_EQ(e.landmarksSplit, 0u);
}

TEST(AssociationErrors, HeaderExampleAccuracyRealCountsTheNullHypothesisAsWrong) {
  const auto e = evaluate(make({{a, 1}, {a, 1}, {b, 1}, {b, std::nullopt}}));
  EXPECT_EQ(e.realTotal, 4u);
  EXPECT_EQ(e.realCorrect, 2u);
  EXPECT_DOUBLE_EQ(e.accuracyReal, 0.5);
}

TEST(AssociationErrors, HeaderExamplePairwisePrecisionSeesAMergeRecallDoesNot) {
  const auto e = evaluate(make({{a, 1}, {a, 1}, {b, 1}}));
  EXPECT_EQ(e.pairsSameEstimate, 3u);
  EXPECT_EQ(e.pairsSameTruth, 1u);
  EXPECT_EQ(e.pairsBoth, 1u);
  EXPECT_DOUBLE_EQ(e.pairwisePrecision, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(e.pairwiseRecall, 1.0);
}

TEST(AssociationErrors, ASplitLowersRecallNotPrecision) {
  // a on two estimates (3 + 2): same-truth pairs C(5,2) = 10, same-estimate pairs 3 + 1 = 4, all of one truth.
  const auto e = evaluate(make({{a, 1}, {a, 1}, {a, 1}, {a, 2}, {a, 2}}));
  EXPECT_DOUBLE_EQ(e.pairwisePrecision, 1.0);
  EXPECT_DOUBLE_EQ(e.pairwiseRecall, 4.0 / 10.0);
  EXPECT_EQ(e.landmarksSplit, 1u);  // header example: 2 of 5 on an estimate matched to nothing
  EXPECT_EQ(e.landmarksMerged, 0u);
}

TEST(AssociationErrors, HeaderExampleMergeCountsTheLandmarkThatLostItsEstimate) {
  const auto e = evaluate(make({{a, 1}, {a, 1}, {a, 1}, {b, 1}, {b, 1}}));
  EXPECT_EQ(e.landmarksMerged, 1u);
  EXPECT_EQ(e.landmarksSplit, 0u);
}

TEST(AssociationErrors, OneStrayDetectionOrUnderTenPercentIsNeitherMergeNorSplit) {
  // One detection of b on a's estimate: below the minimum of 2.
  const auto once = evaluate(make({{a, 1}, {a, 1}, {b, 1}, {b, 2}, {b, 2}}));
  EXPECT_EQ(once.landmarksMerged, 0u);
  // 2 of 25 detections of a on a second estimate: 8 % < 10 %.
  std::vector<std::pair<int, std::optional<int>>> list(23, {a, 1});
  list.push_back({a, 2});
  list.push_back({a, 2});
  EXPECT_EQ(evaluate(make(list)).landmarksSplit, 0u);
  // 3 of 25: 12 % ≥ 10 %.
  list.push_back({a, 2});
  EXPECT_EQ(evaluate(make(list)).landmarksSplit, 1u);
}

TEST(AssociationErrors, StrayDetectionsOnSeveralEstimatesAreNeitherMergeNorSplit) {
  // a's own estimate is 1; one detection on b's estimate 2, one on c's estimate 3, one each on unmatched 8 and 9.
  const auto e = evaluate(make({{a, 1}, {a, 1}, {a, 1}, {a, 1}, {a, 2}, {a, 3}, {a, 8}, {a, 9}, {b, 2}, {b, 2},
                                {c, 3}, {c, 3}}));
  EXPECT_EQ(e.landmarksMerged, 0u);
  EXPECT_EQ(e.landmarksSplit, 0u);
}

TEST(AssociationErrors, UnassignedDetectionsFormNoPairsButCountInTheShare) {
  // a: 2 detections on b's estimate, 18 on the null hypothesis: 10 % of 20 → merged; no pair of a is assigned
  // twice on its own estimate.
  std::vector<std::pair<int, std::optional<int>>> list(18, {a, std::nullopt});
  list.push_back({a, 9});
  list.push_back({a, 9});
  for (int i = 0; i < 5; ++i) list.push_back({b, 9});
  const auto e = evaluate(make(list));
  EXPECT_EQ(e.landmarksMerged, 1u);
  EXPECT_EQ(e.pairsSameTruth, 1u + 10u);     // C(2,2) for a, C(5,2) for b
  EXPECT_EQ(e.pairsSameEstimate, 21u);       // C(7,2)
  EXPECT_NEAR(e.accuracyReal, 5.0 / 25.0, 1e-15);
}

TEST(AssociationErrors, ClutterRejectedIsTheShareOfClutterOnNoLandmark) {
  const auto e = evaluate(make({{a, 1}, {kClutter, std::nullopt}, {kClutter, 1}, {kClutter, 4}, {kClutter, std::nullopt}}));
  EXPECT_EQ(e.clutter, 4u);
  EXPECT_EQ(e.clutterUnassigned, 2u);
  EXPECT_DOUBLE_EQ(e.clutterRejected, 0.5);
  EXPECT_EQ(e.realTotal, 1u);          // clutter is not in accuracy_real
  EXPECT_EQ(e.accuracyReal, 1.0);
}

TEST(AssociationErrors, HeaderExampleClutterSplitsIntoMovingAndFalsePositive) {
  // Clutter with a source (a moving object) on ∅ and on estimate 1, clutter without one on ∅.
  std::vector<DetectionAssociation> d = {{a, 1}, {kClutter, std::nullopt, 3}, {kClutter, 1, 3},
                                         {kClutter, std::nullopt, std::nullopt}};
  const auto e = evaluate(d);
  EXPECT_EQ(e.clutterMoving, 2u);
  EXPECT_EQ(e.clutterMovingUnassigned, 1u);
  EXPECT_DOUBLE_EQ(e.clutterRejectedMoving, 0.5);
  EXPECT_EQ(e.clutterFalsePositive, 1u);
  EXPECT_EQ(e.clutterFalsePositiveUnassigned, 1u);
  EXPECT_DOUBLE_EQ(e.clutterRejectedFalsePositive, 1.0);
  EXPECT_DOUBLE_EQ(e.clutterRejected, 2.0 / 3.0);  // the count-weighted mean of the two
}

TEST(AssociationErrors, ClutterWithoutSourcesIsAllFalsePositives) {
  // A log without clutter sources (every simulated log): the false-positive share is clutter_rejected, the
  // moving one undefined.
  const auto e = evaluate(make({{a, 1}, {kClutter, std::nullopt}, {kClutter, 1}, {kClutter, std::nullopt}}));
  EXPECT_EQ(e.clutterRejectedFalsePositive, e.clutterRejected);
  EXPECT_DOUBLE_EQ(e.clutterRejected, 2.0 / 3.0);
  EXPECT_TRUE(std::isnan(e.clutterRejectedMoving));
  EXPECT_EQ(e.clutterMoving, 0u);
}

TEST(AssociationErrors, OnlyMovingClutterLeavesTheFalsePositiveShareUndefined) {
  const auto e = evaluate({{kClutter, 4, 0}, {kClutter, 4, 0}, {kClutter, std::nullopt, 1}, {kClutter, 4, 0}});
  EXPECT_DOUBLE_EQ(e.clutterRejectedMoving, 0.25);
  EXPECT_EQ(e.clutterRejectedMoving, e.clutterRejected);
  EXPECT_TRUE(std::isnan(e.clutterRejectedFalsePositive));
  // Moving clutter on an estimate is not a real detection: no pair, no accuracy.
  EXPECT_EQ(e.realTotal, 0u);
  EXPECT_EQ(e.pairsSameEstimate, 0u);
}

TEST(AssociationErrors, HeaderExampleTheLostRealDetectionsByWhereTheyWent) {
  const auto e = evaluate(make({{a, 1}, {a, 1}, {a, 1}, {a, 2}, {b, 1}, {b, std::nullopt}, {c, 3}}));
  EXPECT_EQ(e.realCorrect, 4u);
  EXPECT_EQ(e.realOnUnmatchedEstimateCount, 1u);  // a on 2, which the matching gives to no true landmark
  EXPECT_EQ(e.realOnAnotherLandmarkCount, 1u);    // b on 1, a's estimate
  EXPECT_EQ(e.realUnassignedCount, 1u);           // b on the null hypothesis
  EXPECT_DOUBLE_EQ(e.accuracyReal, 4.0 / 7.0);
  EXPECT_DOUBLE_EQ(e.realOnUnmatchedEstimate, 1.0 / 7.0);
  EXPECT_DOUBLE_EQ(e.realOnAnotherLandmark, 1.0 / 7.0);
  EXPECT_DOUBLE_EQ(e.realUnassigned, 1.0 / 7.0);
}

TEST(AssociationErrors, TheLostSharesAndAccuracyRealPartitionTheRealDetections) {
  // Every real detection is counted exactly once: right, unassigned, on another landmark's estimate or on an
  // unmatched one; clutter and unknown truth enter none of the four.
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> truth(kUnknownTruth, 5), estimate(-1, 7);  // kNotALandmark = -1 between
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<DetectionAssociation> d;
    std::size_t real = 0;
    for (int i = 0; i < 40; ++i) {
      const int t = truth(rng);
      const int e = estimate(rng);
      d.push_back({t, e < 0 ? std::nullopt : std::optional<int>(e)});
      if (t >= 0) ++real;
    }
    const AssociationErrors x = evaluate(d);
    ASSERT_EQ(x.realTotal, real);
    EXPECT_EQ(x.realCorrect + x.realUnassignedCount + x.realOnAnotherLandmarkCount + x.realOnUnmatchedEstimateCount,
              real);
    if (real > 0) {
      EXPECT_NEAR(x.accuracyReal + x.realUnassigned + x.realOnAnotherLandmark + x.realOnUnmatchedEstimate, 1.0,
                  1e-12);
    }
  }
}

TEST(AssociationErrors, UndefinedRatiosAreNaN) {
  const auto onlyClutter = evaluate(make({{kClutter, std::nullopt}}));
  EXPECT_TRUE(std::isnan(onlyClutter.accuracyReal));
  EXPECT_TRUE(std::isnan(onlyClutter.realUnassigned));
  EXPECT_TRUE(std::isnan(onlyClutter.realOnAnotherLandmark));
  EXPECT_TRUE(std::isnan(onlyClutter.realOnUnmatchedEstimate));
  EXPECT_TRUE(std::isnan(onlyClutter.pairwisePrecision));
  const auto noClutter = evaluate(make({{a, 1}}));
  EXPECT_TRUE(std::isnan(noClutter.clutterRejected));
  EXPECT_TRUE(std::isnan(noClutter.pairwiseRecall));  // one detection: no pair
}

TEST(AssociationErrors, RenamingTheEstimatesChangesNothing) {
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> truth(-1, 5), estimate(-1, 7);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<DetectionAssociation> d, renamed;
    for (int i = 0; i < 40; ++i) {
      const int t = truth(rng), e = estimate(rng);
      const std::optional<int> est = e < 0 ? std::nullopt : std::optional<int>(e);
      d.push_back({t, est});
      renamed.push_back({t, est ? std::optional<int>(100 + 7 * *est) : std::nullopt});
    }
    const AssociationErrors x = evaluate(d), y = evaluate(renamed);
    EXPECT_EQ(x.realCorrect, y.realCorrect);
    EXPECT_EQ(x.pairsBoth, y.pairsBoth);
    EXPECT_EQ(x.pairsSameEstimate, y.pairsSameEstimate);
    EXPECT_EQ(x.landmarksMerged, y.landmarksMerged);
    EXPECT_EQ(x.landmarksSplit, y.landmarksSplit);
  }
}

TEST(AssociationErrors, UnknownTruthChangesNothing) {
  // A merge, a split, clutter both ways; then the same with detections of truth "unknown" (docs/metrics.md) on
  // a matched estimate, an unmatched one, a new one and the null hypothesis: every count and ratio is unchanged.
  const auto base = make({{a, 1}, {a, 1}, {a, 1}, {b, 1}, {b, 1}, {c, 2}, {c, 2}, {c, 3}, {c, 3}, {kClutter, 2},
                          {kClutter, std::nullopt}});
  auto withUnknown = base;
  for (const std::optional<int> estimate : {std::optional<int>(1), std::optional<int>(3), std::optional<int>(9),
                                            std::optional<int>()}) {
    withUnknown.push_back({kUnknownTruth, estimate});
    withUnknown.push_back({kUnknownTruth, estimate});
  }
  const AssociationErrors x = evaluate(base);
  const AssociationErrors y = evaluate(withUnknown);
  EXPECT_EQ(x.realTotal, y.realTotal);
  EXPECT_EQ(x.realCorrect, y.realCorrect);
  EXPECT_EQ(x.clutter, y.clutter);
  EXPECT_EQ(x.clutterUnassigned, y.clutterUnassigned);
  EXPECT_EQ(x.pairsBoth, y.pairsBoth);
  EXPECT_EQ(x.pairsSameEstimate, y.pairsSameEstimate);
  EXPECT_EQ(x.pairsSameTruth, y.pairsSameTruth);
  EXPECT_EQ(x.landmarksMerged, y.landmarksMerged);
  EXPECT_EQ(x.landmarksSplit, y.landmarksSplit);
  EXPECT_EQ(x.landmarksMerged, 1u);
  EXPECT_EQ(x.landmarksSplit, 1u);
  for (const auto& [p, q] : {std::pair{x.accuracyReal, y.accuracyReal}, std::pair{x.pairwisePrecision, y.pairwisePrecision},
                             std::pair{x.pairwiseRecall, y.pairwiseRecall}, std::pair{x.clutterRejected, y.clutterRejected}}) {
    EXPECT_EQ(p, q);
  }
}

}  // namespace
}  // namespace semslam
