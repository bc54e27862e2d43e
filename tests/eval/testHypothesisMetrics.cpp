// Paper A's hypothesis metrics on hand-made hybrid beliefs: association marginal (eq. 8), class marginal (eq. 7),
// entropy, det of the heaviest component's position covariance, its error, the weighted error, ESS.

#include <gtest/gtest.h>

#include <cmath>

#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

HypothesisComponent component(double weight, AssociationHistory history, std::vector<int> classes, const Pose& pose,
                              const Matrix& covariance = Matrix()) {
  HypothesisComponent c;
  c.weight = weight;
  c.associations = std::move(history);
  c.classes = std::move(classes);
  c.pose = pose;
  c.covariance = covariance;
  return c;
}

std::vector<HypothesisComponent> threeComponents(double scale = 1.0) {
  Matrix3 covariance;
  covariance << 0.04, 0.01, 0.0,  //
      0.01, 0.09, 0.0,            //
      0.0, 0.0, 0.01;
  return {
      component(0.4 * scale, {{1, 2}, {1}}, {0, 1}, SE2(1.0, 0.0, 0.0), covariance),
      component(0.2 * scale, {{1, 2}, {1}}, {1, 1}, SE2(1.2, 0.0, 0.3), Matrix3::Identity()),
      component(0.4 * scale, {{2, 1}, {2}}, {0, 0}, SE2(3.0, 0.0, 0.0), Matrix3::Identity()),
  };
}

TEST(HypothesisMetrics, AssociationMarginalSumsOverClassRealizations) {
  const std::vector<AssociationHypothesis> marginal = associationMarginal(threeComponents());
  ASSERT_EQ(marginal.size(), 2u);
  EXPECT_EQ(marginal[0].associations, (AssociationHistory{{1, 2}, {1}}));
  EXPECT_NEAR(marginal[0].weight, 0.6, 1e-15);
  EXPECT_EQ(marginal[1].associations, (AssociationHistory{{2, 1}, {2}}));
  EXPECT_NEAR(marginal[1].weight, 0.4, 1e-15);
}

TEST(HypothesisMetrics, ClassMarginalPerObject) {
  const Matrix m = classMarginals(threeComponents(), 2);
  ASSERT_EQ(m.rows(), 2);
  ASSERT_EQ(m.cols(), 2);
  EXPECT_NEAR(m(0, 0), 0.8, 1e-15);
  EXPECT_NEAR(m(0, 1), 0.2, 1e-15);
  EXPECT_NEAR(m(1, 0), 0.4, 1e-15);
  EXPECT_NEAR(m(1, 1), 0.6, 1e-15);
  EXPECT_THROW(classMarginals(threeComponents(), 1), InputError);  // class 1 outside [0, 1)
}

TEST(HypothesisMetrics, FourMetricsOfPaperAAndTheEss) {
  for (double scale : {1.0, 37.0}) {  // unnormalised weights give the same numbers
    const HypothesisMetrics m = evaluateHypotheses(threeComponents(scale), Pose(SE2(1.0, 0.5, 0.0)));
    EXPECT_EQ(m.components, 3u);
    EXPECT_EQ(m.histories, 2u);
    EXPECT_NEAR(m.entropy, -(0.6 * std::log(0.6) + 0.4 * std::log(0.4)), 1e-14);
    EXPECT_NEAR(m.heaviestAssociationWeight, 0.6, 1e-15);
    EXPECT_FALSE(m.disambiguated);
    EXPECT_NEAR(m.ess, 1.0 / (0.16 + 0.04 + 0.16), 1e-12);
    EXPECT_EQ(m.heaviestComponent, 0u);  // components 0 and 2 tie at 0.4: the first wins
    EXPECT_NEAR(m.detCovariance, 0.04 * 0.09 - 0.01 * 0.01, 1e-16);
    EXPECT_NEAR(m.errorHeaviest, 0.5, 1e-15);
    const double expected = 0.4 * 0.5 + 0.2 * std::hypot(0.2, 0.5) + 0.4 * std::hypot(2.0, 0.5);
    EXPECT_NEAR(m.errorWeightedAverage, expected, 1e-14);
  }
}

TEST(HypothesisMetrics, OneHistoryOverSeveralClassRealizationsIsDisambiguated) {
  const std::vector<HypothesisComponent> c = {
      component(0.5, {{3}}, {0}, SE2(), Matrix3::Identity()),
      component(0.5, {{3}}, {1}, SE2(), Matrix3::Identity()),
  };
  const HypothesisMetrics m = evaluateHypotheses(c, std::nullopt);
  EXPECT_EQ(m.entropy, 0.0);
  EXPECT_EQ(m.heaviestAssociationWeight, 1.0);
  EXPECT_TRUE(m.disambiguated);
  EXPECT_NEAR(m.ess, 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(m.detCovariance, 1.0);
  EXPECT_TRUE(std::isnan(m.errorHeaviest));  // no true pose
  EXPECT_TRUE(std::isnan(m.errorWeightedAverage));
}

TEST(HypothesisMetrics, SpatialPositionBlock) {
  Matrix6 covariance = Matrix6::Identity();
  covariance.topLeftCorner<3, 3>() = Vector3(1.0, 2.0, 3.0).asDiagonal();
  const HypothesisMetrics m = evaluateHypotheses({component(1.0, {{0}}, {}, SE3(), covariance)},
                                                 Pose(SE3(SO3(), Point3(1.0, 2.0, 2.0))));
  EXPECT_DOUBLE_EQ(m.detCovariance, 6.0);
  EXPECT_DOUBLE_EQ(m.errorHeaviest, 3.0);
  EXPECT_DOUBLE_EQ(m.errorWeightedAverage, 3.0);
}

TEST(HypothesisMetrics, EntropyEssAndFractionOnPlainWeights) {
  EXPECT_NEAR(entropy({1, 1, 1, 1}), std::log(4.0), 1e-15);
  EXPECT_EQ(entropy({0.0, 2.0}), 0.0);
  EXPECT_NEAR(effectiveSampleSize({3, 3, 3}), 3.0, 1e-14);
  EXPECT_NEAR(effectiveSampleSize({1, 0, 0, 0}), 1.0, 1e-15);
  EXPECT_NEAR(effectiveSampleSize({0.9, 0.1}), 1.0 / 0.82, 1e-14);
  EXPECT_DOUBLE_EQ(disambiguatedFraction({0.95, 0.5, 0.91, 0.9}), 0.5);  // 0.9 itself is not "more than 0.9"
  EXPECT_TRUE(std::isnan(disambiguatedFraction({})));
  EXPECT_THROW(entropy({}), InputError);
  EXPECT_THROW(entropy({0.5, -0.1}), InputError);
  EXPECT_THROW(effectiveSampleSize({0.0, 0.0}), InputError);
  EXPECT_THROW(evaluateHypotheses({}, std::nullopt), InputError);
}

}  // namespace
}  // namespace semslam
