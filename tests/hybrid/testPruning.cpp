// PruneAndNormalize (Algorithm 1, line 7): invariants.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "semslam/hybrid/Pruning.h"
#include "semslam/models/Sampling.h"

using namespace semslam;

TEST(Pruning, KeepsWeightsAboveTheThresholdNormalisedAndTheHeaviest) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 40;
    std::vector<double> logWeights(n);
    for (double& l : logWeights) l = 12.0 * standardNormal(rng) + 300.0;  // far from 0: log space matters
    if (trial % 7 == 0) logWeights[0] = -std::numeric_limits<double>::infinity();
    if (n == 1) logWeights[0] = 1.0;
    const double ratio = 150.0;
    const int cap = trial % 3 == 0 ? 5 : 0;
    const PruningResult result = pruneAndNormalize(logWeights, ratio, cap);
    const std::vector<double> input = normalizeLogWeights(logWeights);
    const std::size_t heaviest = std::max_element(input.begin(), input.end()) - input.begin();

    ASSERT_FALSE(result.kept.empty());
    EXPECT_TRUE(std::is_sorted(result.kept.begin(), result.kept.end()));
    EXPECT_NEAR(std::accumulate(result.weights.begin(), result.weights.end(), 0.0), 1.0, 1e-12);
    EXPECT_NE(std::find(result.kept.begin(), result.kept.end(), heaviest), result.kept.end());
    if (cap > 0) EXPECT_LE(result.kept.size(), static_cast<std::size_t>(cap));
    std::size_t aboveRatio = 0;
    for (double w : input) aboveRatio += (w > 0.0 && w >= input[heaviest] / ratio) ? 1 : 0;
    EXPECT_EQ(result.capped, aboveRatio - result.kept.size());
    double kept = 0.0;
    for (std::size_t i = 0; i < result.kept.size(); ++i) {
      EXPECT_GT(result.weights[i], 0.0);
      EXPECT_GE(input[result.kept[i]], input[heaviest] / ratio);
      kept += input[result.kept[i]];
    }
    EXPECT_NEAR(result.prunedMass, 1.0 - kept, 1e-12);
    if (cap == 0) {  // everything at or above the threshold survives
      std::size_t above = 0;
      for (double w : input) above += (w > 0.0 && w >= input[heaviest] / ratio) ? 1 : 0;
      EXPECT_EQ(result.kept.size(), above);
    }
  }
}

TEST(Pruning, RatioAtMostOneKeepsEveryPositiveWeight) {
  const PruningResult result = pruneAndNormalize({0.0, -50.0, -std::numeric_limits<double>::infinity(), -800.0}, 0.0);
  EXPECT_EQ(result.kept, (std::vector<std::size_t>{0, 1}));  // exp(−800) underflows to 0
}

TEST(Pruning, RejectsAllZeroAndNaN) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(pruneAndNormalize({-inf, -inf}, 150.0), std::invalid_argument);
  EXPECT_THROW(pruneAndNormalize({0.0, std::nan("")}, 150.0), std::invalid_argument);
}
