// Chi-square CDF and quantiles. Reference values are textbook table entries and, to more digits, values computed
// with mpmath at 40 significant digits (regularized incomplete gamma, then bisection).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "semslam/core/ChiSquare.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

struct QuantileCase {
  double p, dof, expected;
};

TEST(ChiSquare, QuantilesMatchTables) {
  // The usual table entries.
  EXPECT_NEAR(chiSquareQuantile(0.975, 3), 9.348, 5e-4);
  EXPECT_NEAR(chiSquareQuantile(0.025, 3), 0.2158, 5e-5);
  EXPECT_NEAR(chiSquareQuantile(0.95, 2), 5.991, 5e-4);
  EXPECT_NEAR(chiSquareQuantile(0.99, 10), 23.209, 5e-4);
}

TEST(ChiSquare, QuantilesMatchHighPrecisionReferences) {
  const QuantileCase cases[] = {
      {0.975, 3, 9.3484036044961458},     {0.025, 3, 0.21579528262389788},
      {0.95, 1, 3.8414588206941245},      {0.05, 1, 0.0039321400000195232},
      {0.5, 1, 0.45493642311957275},      {0.975, 100, 129.56119718583659},
      {0.025, 100, 74.221927474923726},   {0.999, 5, 20.515005652432876},
      {1e-6, 4, 0.0028297613229586858},   {0.975, 0.5, 3.4332352999607744},
      {0.025, 6, 1.2373442457912026},     {1e-10, 1, 1.5707963267948967e-20},
  };
  for (const QuantileCase& c : cases) {
    EXPECT_NEAR(chiSquareQuantile(c.p, c.dof), c.expected, 1e-12 * c.expected) << "p " << c.p << " dof " << c.dof;
  }
}

TEST(ChiSquare, QuantilesForLargeDegreesOfFreedom) {
  // NEES bands over many poses: k = n d reaches tens or hundreds of thousands.
  const QuantileCase cases[] = {
      {0.975, 1000, 1089.5309127749135},     {0.025, 1000, 914.25715379925894},
      {0.975, 30000, 30481.982656347922},    {0.025, 30000, 29521.805937252692},
      {0.975, 300000, 301520.07499122442},   {0.025, 300000, 298483.71361872051},
  };
  for (const QuantileCase& c : cases) {
    EXPECT_NEAR(chiSquareQuantile(c.p, c.dof), c.expected, 1e-11 * c.expected) << "p " << c.p << " dof " << c.dof;
  }
}

TEST(ChiSquare, TwoDegreesOfFreedomInClosedForm) {
  // F_2(x) = 1 − exp(−x/2), so F_2⁻¹(p) = −2 log(1 − p), down to the far tails.
  for (double p : {1e-300, 1e-12, 0.01, 0.3, 0.5, 0.9, 0.999, 1.0 - 1e-12}) {
    const double expected = -2.0 * std::log1p(-p);
    EXPECT_NEAR(chiSquareQuantile(p, 2), expected, 1e-12 * expected) << p;
  }
  for (double x : {1e-8, 0.5, 3.0, 40.0, 700.0}) {
    EXPECT_NEAR(chiSquareCdf(x, 2), -std::expm1(-x / 2), 1e-15);
    EXPECT_NEAR(chiSquareSurvival(x, 2), std::exp(-x / 2), 1e-13 * std::exp(-x / 2));
  }
}

TEST(ChiSquare, EvenDegreesOfFreedomMatchThePoissonSum) {
  // For k = 2m: 1 − F_k(x) = e^{−x/2} Σ_{j<m} (x/2)^j / j!.
  for (int m : {1, 2, 5, 20}) {
    for (double x : {0.3, 2.0, 9.0, 30.0, 80.0}) {
      const double y = x / 2;
      double term = std::exp(-y), sum = 0.0;
      for (int j = 0; j < m; ++j) {
        sum += term;
        term *= y / (j + 1);
      }
      EXPECT_NEAR(chiSquareSurvival(x, 2 * m), sum, 1e-13 * sum + 1e-300) << m << " " << x;
      EXPECT_NEAR(chiSquareCdf(x, 2 * m) + chiSquareSurvival(x, 2 * m), 1.0, 1e-15);
    }
  }
  EXPECT_NEAR(chiSquareSurvival(50.0, 3), 7.9891792449514711e-11, 1e-23);  // mpmath
  EXPECT_NEAR(chiSquareCdf(0.001, 1), 0.025227120630039611, 1e-17);       // mpmath
  EXPECT_NEAR(chiSquareCdf(29500.0, 30000), 0.020183788056918469, 1e-13);  // mpmath
}

TEST(ChiSquare, QuantileInvertsTheCdf) {
  for (double dof : {0.3, 1.0, 3.0, 7.5, 60.0, 5000.0}) {
    for (double p : {1e-8, 0.001, 0.025, 0.4, 0.5, 0.6, 0.975, 0.999999}) {
      const double x = chiSquareQuantile(p, dof);
      const double back = p <= 0.5 ? chiSquareCdf(x, dof) : 1.0 - chiSquareSurvival(x, dof);
      EXPECT_NEAR(back, p, 1e-12 * std::max(p, 1e-3)) << dof << " " << p;
    }
  }
}

TEST(ChiSquare, DensityIntegratesToTheCdf) {
  // Simpson's rule on [1, 4] for k = 3.
  const int n = 2000;
  const double a = 1.0, b = 4.0, h = (b - a) / n;
  double sum = chiSquareDensity(a, 3) + chiSquareDensity(b, 3);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * chiSquareDensity(a + i * h, 3);
  EXPECT_NEAR(sum * h / 3.0, chiSquareCdf(b, 3) - chiSquareCdf(a, 3), 1e-12);
  EXPECT_NEAR(chiSquareDensity(2.0, 2), 0.5 * std::exp(-1.0), 1e-16);
}

TEST(ChiSquare, EdgesAndInvalidArguments) {
  EXPECT_EQ(chiSquareQuantile(0.0, 3), 0.0);
  EXPECT_EQ(chiSquareQuantile(1.0, 3), std::numeric_limits<double>::infinity());
  EXPECT_EQ(chiSquareCdf(0.0, 3), 0.0);
  EXPECT_EQ(chiSquareSurvival(0.0, 3), 1.0);
  EXPECT_THROW(chiSquareQuantile(-0.1, 3), InputError);
  EXPECT_THROW(chiSquareQuantile(1.1, 3), InputError);
  EXPECT_THROW(chiSquareQuantile(std::numeric_limits<double>::quiet_NaN(), 3), InputError);
  EXPECT_THROW(chiSquareQuantile(0.5, 0.0), InputError);
  EXPECT_THROW(chiSquareCdf(-1.0, 3), InputError);
  EXPECT_THROW(regularizedGammaP(-1.0, 1.0), InputError);
}

}  // namespace
}  // namespace semslam
