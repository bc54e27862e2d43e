// Statistics of an error vector, checked by hand against numpy's definitions (population std, median of the
// two middle values for even sizes).

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "semslam/eval/ErrorStatistics.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

TEST(ErrorStatistics, SmallEvenVectorByHand) {
  const ErrorStatistics s = computeErrorStatistics({3.0, 1.0, 4.0, 2.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);           // (2 + 3) / 2
  EXPECT_DOUBLE_EQ(s.sse, 30.0);             // 9 + 1 + 16 + 4
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(7.5));  // sqrt(30 / 4)
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));  // population: (2.25 + 2.25 + 0.25 + 0.25) / 4
}

TEST(ErrorStatistics, SmallOddVectorByHand) {
  const ErrorStatistics s = computeErrorStatistics({0.5, 2.0, 0.5});
  EXPECT_DOUBLE_EQ(s.median, 0.5);
  EXPECT_DOUBLE_EQ(s.mean, 1.0);
  EXPECT_DOUBLE_EQ(s.sse, 4.5);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(1.5));
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(0.5));  // (0.25 + 1 + 0.25) / 3
  EXPECT_DOUBLE_EQ(s.max, 2.0);
  EXPECT_DOUBLE_EQ(s.min, 0.5);
}

TEST(ErrorStatistics, SingleValueHasZeroSpread) {
  const ErrorStatistics s = computeErrorStatistics({0.7});
  EXPECT_DOUBLE_EQ(s.median, 0.7);
  EXPECT_DOUBLE_EQ(s.rmse, 0.7);
  EXPECT_DOUBLE_EQ(s.std, 0.0);
}

TEST(ErrorStatistics, EmptyIsAnInputError) { EXPECT_THROW(computeErrorStatistics({}), InputError); }

TEST(ErrorStatistics, PairwiseSumIsExactOnIntegersAndCloseOnRandomData) {
  for (const std::size_t n : {0u, 1u, 7u, 8u, 9u, 127u, 128u, 129u, 1000u, 4541u}) {
    std::vector<double> values(n);
    std::iota(values.begin(), values.end(), 1.0);
    EXPECT_EQ(pairwiseSum(values.data(), n), static_cast<double>(n) * static_cast<double>(n + 1) / 2.0) << n;
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> values(10007);
  for (double& v : values) v = uniform(rng);
  long double exact = 0.0L;
  for (const double v : values) exact += v;
  EXPECT_NEAR(pairwiseSum(values.data(), values.size()), static_cast<double>(exact), 1e-11);
}

}  // namespace
}  // namespace semslam
