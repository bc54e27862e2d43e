// MaxMixtureFactor (paper B, sec. IV-C): choice of component, explicit normalisation, continuity at a switch,
// Jacobians on both sides of a switch, and the null hypothesis.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "semslam/factors/MaxMixtureFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/factors/RangeBearingFactor.h"
#include "semslam/factors/SeenPointMove.h"
#include "semslam/graph/NoiseModel.h"
#include "support/FactorTesting.h"

using namespace semslam;
using semslam::test::expectJacobiansMatch;

namespace {

const Key kRobot = poseKey(0);
const Key kNear = landmarkKey(0);
const Key kFar = landmarkKey(1);

FactorPtr rangeBearing(Key landmark, const Vector2& z, double sigmaScale = 1.0) {
  return std::make_shared<const RangeBearingFactor<Point2>>(
      kRobot, landmark, z, NoiseModel::fromSigmas(Vector2(0.1, 0.02) * sigmaScale));
}

/// A detection of two candidate landmarks at (4, 0) and (4, 1): the robot's y decides which one it sees.
Values twoLandmarks(double robotY) {
  Values values;
  values.insert(kRobot, SE2(0.0, robotY, 0.0));
  values.insert(kNear, Point2(4.0, 0.0));
  values.insert(kFar, Point2(4.0, 1.0));
  return values;
}

/// −log(w_i p_i(z | X)) of one Gaussian component, from its chi2 and normaliser.
double negativeLogComponent(const Factor& factor, double weight, const Values& values) {
  return 0.5 * factor.chi2(values) + *factor.logNormalizer() - std::log(weight);
}

}  // namespace

TEST(MaxMixtureFactor, KeysAreTheUnionOfTheComponentsKeys) {
  const Vector2 z(4.0, 0.0);
  const MaxMixtureFactor mixture({{rangeBearing(kNear, z), 0.5}, {rangeBearing(kFar, z), 0.5}});
  EXPECT_EQ(mixture.keys(), (std::vector<Key>{kRobot, kNear, kFar}));
  EXPECT_EQ(mixture.errorDimension(), 3);
}

TEST(MaxMixtureFactor, CostIsTheLargestComponentsNegativeLogLikelihoodUpToAConstant) {
  const Vector2 z(4.0, 0.0);
  const std::vector<MaxMixtureFactor::Component> components = {{rangeBearing(kNear, z), 0.7},
                                                               {rangeBearing(kFar, z, 3.0), 0.3}};
  const MaxMixtureFactor mixture(components);
  // The constant is min_i c_i: recover it at one point, then it must hold everywhere.
  double constant = std::nan("");
  for (double y : {-1.0, -0.2, 0.0, 0.3, 0.5, 0.8, 1.0, 1.7}) {
    const Values values = twoLandmarks(y);
    double best = std::numeric_limits<double>::infinity();
    for (const auto& c : components) best = std::min(best, negativeLogComponent(*c.factor, c.weight, values));
    const double offset = best - 0.5 * mixture.chi2(values);
    if (std::isnan(constant)) constant = offset;
    EXPECT_NEAR(offset, constant, 1e-9) << "y = " << y;
    LinearizedFactor linearized;
    mixture.linearize(values, linearized);
    EXPECT_NEAR(linearized.whitenedError.squaredNorm(), mixture.chi2(values), 1e-9);
  }
}

TEST(MaxMixtureFactor, SwitchesComponentAndStaysContinuousAtTheSwitch) {
  const Vector2 z(4.0, 0.0);
  const MaxMixtureFactor mixture({{rangeBearing(kNear, z), 0.5}, {rangeBearing(kFar, z), 0.5}});
  EXPECT_EQ(mixture.activeComponent(twoLandmarks(0.0)), 0);
  EXPECT_EQ(mixture.activeComponent(twoLandmarks(1.0)), 1);
  // Bisect for the switch, then the cost on both sides must agree to the bisection's resolution.
  double below = 0.0, above = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double middle = 0.5 * (below + above);
    (mixture.activeComponent(twoLandmarks(middle)) == 0 ? below : above) = middle;
  }
  EXPECT_NEAR(mixture.chi2(twoLandmarks(below)), mixture.chi2(twoLandmarks(above)), 1e-6);
  EXPECT_NEAR(0.5 * (below + above), 0.5, 1e-6);  // equal weights and noise: the switch is half-way
}

TEST(MaxMixtureFactor, JacobiansMatchFiniteDifferencesOnBothSidesOfASwitch) {
  const Vector2 z(4.0, 0.05);
  const MaxMixtureFactor mixture({{rangeBearing(kNear, z), 0.6}, {rangeBearing(kFar, z, 2.0), 0.4}});
  int checked = 0;
  for (double y : {-0.5, 0.2, 0.45, 0.7, 1.2}) {
    const Values values = twoLandmarks(y);
    // Away from the switch itself (within a finite-difference step the choice must not change).
    const int here = mixture.activeComponent(values);
    Values nudged = values;
    nudged.update(kRobot, SE2(0.0, y + 1e-5, 0.0));
    if (mixture.activeComponent(nudged) != here) continue;
    expectJacobiansMatch(mixture, values);
    ++checked;
    LinearizedFactor linearized;
    mixture.linearize(values, linearized);
    const int untouched = here == 0 ? 2 : 1;  // the other candidate's key gets a zero Jacobian
    EXPECT_TRUE(linearized.jacobians[untouched].isZero(0.0)) << "y = " << y;
  }
  EXPECT_GE(checked, 4);  // the skip above is for a point within a finite-difference step of the switch only
  EXPECT_EQ(mixture.activeComponent(twoLandmarks(-0.5)), 0);
  EXPECT_EQ(mixture.activeComponent(twoLandmarks(1.2)), 1);
}

TEST(MaxMixtureFactor, NullHypothesisWinsForAnOutlierAndLosesForAnInlier) {
  // Paper B's null hypothesis: the same measurement with a broad Gaussian (100 sigma) and weight 0.1.
  const Values values = twoLandmarks(0.0);
  auto mixtureFor = [](const Vector2& z) {
    return MaxMixtureFactor({{rangeBearing(kNear, z), 0.9}, {rangeBearing(kNear, z, 100.0), 0.1}});
  };
  EXPECT_EQ(mixtureFor(Vector2(4.05, 0.01)).activeComponent(values), 0);  // inlier: within 1 sigma
  EXPECT_EQ(mixtureFor(Vector2(7.0, 0.8)).activeComponent(values), 1);    // outlier: 30 sigma off in range
}

TEST(MaxMixtureFactor, ItsChoiceIsVisibleThroughTheFactorInterfaceAndOrdinaryFactorsHaveNone) {
  // The smoothers re-choose components through Factor::activeComponent (docs/incremental-smoother.md, "Mixtures").
  const Vector2 z(4.0, 0.0);
  const FactorPtr mixture = std::make_shared<const MaxMixtureFactor>(
      std::vector<MaxMixtureFactor::Component>{{rangeBearing(kNear, z), 0.5}, {rangeBearing(kFar, z), 0.5}});
  EXPECT_EQ(mixture->activeComponent(twoLandmarks(0.0)), 0);
  EXPECT_EQ(mixture->activeComponent(twoLandmarks(1.0)), 1);
  EXPECT_EQ(rangeBearing(kNear, z)->activeComponent(twoLandmarks(0.0)), -1);
}

TEST(MaxMixtureFactor, RejectsBadComponents) {
  const Vector2 z(4.0, 0.0);
  EXPECT_THROW(MaxMixtureFactor({}), std::invalid_argument);
  EXPECT_THROW(MaxMixtureFactor({{rangeBearing(kNear, z), 0.0}}), std::invalid_argument);
  EXPECT_THROW(MaxMixtureFactor({{rangeBearing(kNear, z), std::nan("")}}), std::invalid_argument);
  const auto robust = std::make_shared<const PriorFactor<Point2>>(
      kNear, Point2(0, 0), NoiseModel::isotropic(2, 1.0)->withRobustKernel(std::make_shared<HuberKernel>(1.0)));
  EXPECT_THROW(MaxMixtureFactor({{robust, 1.0}}), std::invalid_argument);
}

TEST(MaxMixtureFactor, AWidenedComponentChoosesAndCostsAsTheSameFactorEvaluatedOnItsOwn) {
  // Paper B's null hypothesis: the best candidate's factor with σ × 100. Declared a widening, the mixture reuses
  // that candidate's chi2 (over s²); the choice, cost and linearisation must equal the undeclared mixture's.
  const Vector2 z(4.0, 0.0);
  const double scale = 100.0;
  const MaxMixtureFactor plain({{rangeBearing(kNear, z), 0.45}, {rangeBearing(kFar, z), 0.45},
                                {rangeBearing(kNear, z, scale), 0.1}});
  const MaxMixtureFactor widened({{rangeBearing(kNear, z), 0.45},
                                  {rangeBearing(kFar, z), 0.45},
                                  {rangeBearing(kNear, z, scale), 0.1, MaxMixtureFactor::Widening{0, scale}}});
  std::set<int> chosen;
  for (double y : {-6.0, -2.0, -0.6, 0.0, 0.4, 1.0, 1.5, 3.0, 8.0}) {
    const Values values = twoLandmarks(y);
    chosen.insert(plain.activeComponent(values));
    EXPECT_EQ(widened.activeComponent(values), plain.activeComponent(values)) << "y = " << y;
    EXPECT_NEAR(widened.chi2(values), plain.chi2(values), 1e-9 * std::max(1.0, plain.chi2(values))) << "y = " << y;
    LinearizedFactor a, b;
    plain.linearize(values, a);
    widened.linearize(values, b);
    EXPECT_TRUE(a.whitenedError.isApprox(b.whitenedError, 1e-12)) << "y = " << y;
  }
  EXPECT_EQ(chosen, (std::set<int>{0, 1, 2}));  // every component chosen somewhere, the null far off
}

TEST(MaxMixtureFactor, AWideningThatIsNotOneIsRefused) {
  const Vector2 z(4.0, 0.0);
  using Widening = MaxMixtureFactor::Widening;
  auto build = [&](FactorPtr widenedFactor, Widening widening) {
    return MaxMixtureFactor({{rangeBearing(kNear, z), 0.5}, {widenedFactor, 0.5, widening}});
  };
  EXPECT_NO_THROW(build(rangeBearing(kNear, z, 10.0), Widening{0, 10.0}));
  EXPECT_THROW(build(rangeBearing(kNear, z, 10.0), Widening{0, 5.0}), std::invalid_argument);   // wrong scale
  EXPECT_THROW(build(rangeBearing(kFar, z, 10.0), Widening{0, 10.0}), std::invalid_argument);   // other keys
  EXPECT_THROW(build(rangeBearing(kNear, z, 10.0), Widening{1, 10.0}), std::invalid_argument);  // not earlier
  EXPECT_THROW(build(rangeBearing(kNear, z, 0.5), Widening{0, 0.5}), std::invalid_argument);    // narrower
}

TEST(MaxMixtureFactor, AChoiceHoldsWithinItsReach) {
  // Paper B's mixture of one candidate and its widened null, chosen at robot positions across both sides of the
  // switch and moved, robot and landmark, by every size: wherever the landmark seen from the robot moved by less
  // than the choice's reach, activeComponent must not have changed; the reach must be large where the choice is
  // clear (else it saves nothing), and moves across the switch must happen (else the test proves nothing).
  const double scale = 100.0;
  const Vector2 z(4.0, 0.0);
  const MaxMixtureFactor mixture({{rangeBearing(kNear, z), 0.9},
                                  {rangeBearing(kNear, z, scale), 0.1, MaxMixtureFactor::Widening{0, scale}}});
  const auto at = [](double y, double landmarkX) {
    Values values;
    values.insert(kRobot, SE2(0.0, y, 0.1 * y));
    values.insert(kNear, Point2(landmarkX, 0.0));
    return values;
  };
  int withinReach = 0, switched = 0, clear = 0;
  for (double y = -3.0; y <= 3.0; y += 0.05) {
    const Values values = at(y, 4.0);
    const MaxMixtureFactor::Choice choice = mixture.chooseAt(values);
    EXPECT_EQ(choice.component, mixture.activeComponent(values));
    if (std::abs(y) < 0.05) {
      ++clear;
      EXPECT_GT(choice.reach, 0.01) << "y " << y;  // an inlier within a σ: centimetres before the null could win
    }
    for (double move : {-1.0, -0.3, -0.1, -1e-2, -1e-3, -1e-5, 1e-5, 1e-3, 1e-2, 0.1, 0.3, 1.0}) {
      const Values moved = at(y + move, 4.0 - 0.5 * move);
      const int there = mixture.activeComponent(moved);
      if (there != choice.component) ++switched;
      const double distance = seenPointMove(values.at<SE2>(kRobot), values.at<Point2>(kNear), moved.at<SE2>(kRobot),
                                            moved.at<Point2>(kNear));
      if (distance < choice.reach) {
        ++withinReach;
        EXPECT_EQ(there, choice.component) << "y " << y << ", move " << move;
      }
    }
  }
  EXPECT_EQ(clear, 2);
  EXPECT_GT(switched, 50);
  EXPECT_GT(withinReach, 500);
}

TEST(MaxMixtureFactor, AChoiceHasNoReachAcrossLandmarksOrThroughAComponentWithoutABound) {
  const Values values = twoLandmarks(0.0);
  // Components on two landmarks: each may move its own way, so no single reach.
  const MaxMixtureFactor twoLandmarkMixture({{rangeBearing(kNear, Vector2(4.0, 0.0)), 0.5},
                                             {rangeBearing(kFar, Vector2(4.0, 0.0)), 0.5}});
  EXPECT_EQ(twoLandmarkMixture.chooseAt(values).reach, 0.0);
  // A prior gives no bound for a seen move.
  const auto prior = std::make_shared<const PriorFactor<SE2>>(kRobot, SE2(), NoiseModel::isotropic(3, 1.0));
  const MaxMixtureFactor withPrior({{rangeBearing(kNear, Vector2(4.0, 0.0)), 0.5}, {prior, 0.5}});
  EXPECT_EQ(withPrior.chooseAt(values).reach, 0.0);
  EXPECT_EQ(withPrior.chooseAt(values).component, withPrior.activeComponent(values));
  // The same mixture without the prior has one.
  const MaxMixtureFactor alone({{rangeBearing(kNear, Vector2(4.0, 0.0)), 0.5},
                                {rangeBearing(kNear, Vector2(4.0, 0.0), 100.0), 0.5}});
  EXPECT_GT(alone.chooseAt(values).reach, 0.0);
}
