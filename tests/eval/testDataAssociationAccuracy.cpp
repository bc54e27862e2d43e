// Data association accuracy through the shared-detection matching: hand-made cases (renaming, split and merged
// landmarks, null hypothesis for clutter and for real detections) and a randomised renaming check.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

#include "semslam/eval/DataAssociationAccuracy.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

constexpr int kClutter = kNotALandmark;

std::vector<DetectionAssociation> make(const std::vector<std::pair<int, std::optional<int>>>& list) {
  std::vector<DetectionAssociation> out;
  for (const auto& [truth, estimate] : list) out.push_back({truth, estimate});
  return out;
}

TEST(DataAssociationAccuracy, PerfectAssociationUnderArbitraryNames) {
  const auto d = make({{0, 10}, {0, 10}, {1, 11}, {1, 11}, {2, 12}});
  const DataAssociationAccuracy a = evaluateDataAssociation(d);
  EXPECT_EQ(a.correct, 5u);
  EXPECT_EQ(a.total, 5u);
  EXPECT_DOUBLE_EQ(a.accuracy, 1.0);
  ASSERT_EQ(a.matching.pairs.size(), 3u);
  EXPECT_EQ(a.matching.truthOf(10), 0);
  EXPECT_EQ(a.matching.truthOf(11), 1);
  EXPECT_EQ(a.matching.truthOf(12), 2);
  EXPECT_EQ(a.matching.estimateOf(2), 12);
  EXPECT_FALSE(a.matching.truthOf(13));
  EXPECT_EQ(a.matching.sharedDetections(), 5u);
}

TEST(DataAssociationAccuracy, RenamingEstimatedLandmarksChangesNothing) {
  const auto d = make({{0, 3}, {0, 3}, {0, 4}, {1, 4}, {1, 4}, {2, 5}, {kClutter, 5}, {kClutter, std::nullopt},
                       {2, std::nullopt}, {3, 3}});
  const DataAssociationAccuracy a = evaluateDataAssociation(d);
  const std::map<int, int> rename = {{3, 900}, {4, -7}, {5, 42}};
  auto renamed = d;
  for (auto& x : renamed) {
    if (x.estimate) x.estimate = rename.at(*x.estimate);
  }
  const DataAssociationAccuracy b = evaluateDataAssociation(renamed);
  EXPECT_EQ(a.correct, b.correct);
  EXPECT_EQ(a.accuracy, b.accuracy);
  EXPECT_EQ(a.matching.pairs.size(), b.matching.pairs.size());
  for (const LandmarkPair& p : a.matching.pairs) EXPECT_EQ(b.matching.truthOf(rename.at(p.estimated)), p.truth);
  // 3 ↔ 0 (2 shared), 4 ↔ 1 (2), 5 ↔ 2 (1); clutter rejected once: 6 of 10.
  EXPECT_EQ(a.correct, 6u);
  EXPECT_DOUBLE_EQ(a.accuracy, 0.6);
}

TEST(DataAssociationAccuracy, RandomRenamingsKeepTheAccuracy) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> truth(-1, 5), estimate(-1, 7);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<DetectionAssociation> d;
    for (int k = 0; k < 40; ++k) {
      const int e = estimate(rng);
      d.push_back({truth(rng), e < 0 ? std::nullopt : std::optional<int>(e)});
    }
    std::vector<int> names(8);
    std::iota(names.begin(), names.end(), 100);
    std::shuffle(names.begin(), names.end(), rng);
    auto renamed = d;
    for (auto& x : renamed) {
      if (x.estimate) x.estimate = names[*x.estimate];
    }
    const DataAssociationAccuracy a = evaluateDataAssociation(d), b = evaluateDataAssociation(renamed);
    EXPECT_EQ(a.correct, b.correct) << trial;
    EXPECT_EQ(a.matching.sharedDetections(), b.matching.sharedDetections()) << trial;
  }
}

TEST(DataAssociationAccuracy, ASplitLandmarkGetsCreditForItsLargerPart) {
  // True landmark 0 seen four times; the estimate split it into 5 (three detections) and 6 (one).
  const DataAssociationAccuracy a = evaluateDataAssociation(make({{0, 5}, {0, 5}, {0, 6}, {0, 5}}));
  EXPECT_EQ(a.correct, 3u);
  EXPECT_DOUBLE_EQ(a.accuracy, 0.75);
  ASSERT_EQ(a.matching.pairs.size(), 1u);
  EXPECT_EQ(a.matching.truthOf(5), 0);
  EXPECT_FALSE(a.matching.truthOf(6));
}

TEST(DataAssociationAccuracy, MergedLandmarksGetCreditForOneOfThem) {
  const DataAssociationAccuracy a = evaluateDataAssociation(make({{0, 7}, {0, 7}, {1, 7}, {1, 7}, {1, 7}}));
  EXPECT_EQ(a.correct, 3u);
  EXPECT_DOUBLE_EQ(a.accuracy, 0.6);
  EXPECT_EQ(a.matching.truthOf(7), 1);
}

TEST(DataAssociationAccuracy, TheMatchingMaximisesSharedDetectionsNotGreedily) {
  // Greedy would pair A(=1) with truth 0 (3 shared) and leave B(=2) unmatched: 3 correct. The optimum pairs
  // A with truth 1 (2) and B with truth 0 (2): 4 correct.
  const DataAssociationAccuracy a =
      evaluateDataAssociation(make({{0, 1}, {0, 1}, {0, 1}, {1, 1}, {1, 1}, {0, 2}, {0, 2}}));
  EXPECT_EQ(a.correct, 4u);
  EXPECT_EQ(a.matching.truthOf(1), 1);
  EXPECT_EQ(a.matching.truthOf(2), 0);
  EXPECT_NEAR(a.accuracy, 4.0 / 7.0, 1e-15);
}

TEST(DataAssociationAccuracy, NullHypothesisIsRightOnlyForClutter) {
  const DataAssociationAccuracy clutterRejected = evaluateDataAssociation(make({{kClutter, std::nullopt}}));
  EXPECT_EQ(clutterRejected.correct, 1u);
  EXPECT_EQ(clutterRejected.nullChosen, 1u);
  EXPECT_EQ(clutterRejected.clutter, 1u);
  EXPECT_EQ(clutterRejected.clutterRejected, 1u);

  const DataAssociationAccuracy realDropped = evaluateDataAssociation(make({{3, std::nullopt}}));
  EXPECT_EQ(realDropped.correct, 0u);
  EXPECT_EQ(realDropped.nullChosen, 1u);
  EXPECT_EQ(realDropped.clutter, 0u);

  // Clutter that creates its own landmark, or joins a real one, is wrong either way.
  const DataAssociationAccuracy clutterAssociated = evaluateDataAssociation(make({{kClutter, 8}, {0, 9}, {kClutter, 9}}));
  EXPECT_EQ(clutterAssociated.correct, 1u);
  EXPECT_EQ(clutterAssociated.total, 3u);
  EXPECT_EQ(clutterAssociated.nullChosen, 0u);
  EXPECT_EQ(clutterAssociated.clutter, 2u);
  EXPECT_FALSE(clutterAssociated.matching.truthOf(8));  // a landmark made only of clutter matches nothing
}

TEST(DataAssociationAccuracy, EmptyInputAndInvalidTruth) {
  const DataAssociationAccuracy none = evaluateDataAssociation({});
  EXPECT_TRUE(std::isnan(none.accuracy));
  EXPECT_EQ(none.total, 0u);
  EXPECT_THROW(evaluateDataAssociation(make({{-3, 1}})), InputError);
}

TEST(DataAssociationAccuracy, UnknownTruthChangesNothing) {
  // kUnknownTruth (docs/metrics.md) is left out: on any estimate, on the null hypothesis, or alone.
  const auto base = make({{0, 3}, {0, 3}, {0, 4}, {1, 4}, {1, 4}, {kClutter, 5}, {kClutter, std::nullopt}});
  auto withUnknown = base;
  for (const std::optional<int> estimate : {std::optional<int>(3), std::optional<int>(4), std::optional<int>(9),
                                            std::optional<int>()}) {
    withUnknown.push_back({kUnknownTruth, estimate});
  }
  const DataAssociationAccuracy a = evaluateDataAssociation(base);
  const DataAssociationAccuracy b = evaluateDataAssociation(withUnknown);
  EXPECT_EQ(a.correct, b.correct);
  EXPECT_EQ(a.total, b.total);
  EXPECT_EQ(a.nullChosen, b.nullChosen);
  EXPECT_EQ(a.clutter, b.clutter);
  EXPECT_EQ(a.clutterRejected, b.clutterRejected);
  EXPECT_EQ(a.accuracy, b.accuracy);
  EXPECT_EQ(a.matching.pairs.size(), b.matching.pairs.size());
  for (const LandmarkPair& p : a.matching.pairs) EXPECT_EQ(b.matching.truthOf(p.estimated), p.truth);
  EXPECT_FALSE(b.matching.truthOf(9));  // an estimate seen only by unknown detections matches nothing
  const DataAssociationAccuracy onlyUnknown = evaluateDataAssociation(make({{kUnknownTruth, 1}}));
  EXPECT_EQ(onlyUnknown.total, 0u);
  EXPECT_TRUE(std::isnan(onlyUnknown.accuracy));
}

}  // namespace
}  // namespace semslam
