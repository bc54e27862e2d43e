// ViewpointSemanticFactor (A, eq. 2, 10, 18): Jacobians against central finite differences, and the factor's
// density against the classifier model's own log-likelihood.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "semslam/factors/ViewpointSemanticFactor.h"
#include "semslam/models/AnalyticViewpointClassifier.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/TabulatedViewpointClassifier.h"
#include "support/FactorTesting.h"

using namespace semslam;
using semslam::test::expectJacobiansMatch;

namespace {

SE2 randomPose(std::mt19937& rng, double extent) {
  return SE2(extent * (2 * uniform01(rng) - 1), extent * (2 * uniform01(rng) - 1), 3.0 * (2 * uniform01(rng) - 1));
}

}  // namespace

TEST(ViewpointSemanticFactor, JacobiansMatchFiniteDifferencesForBothClassesWithASensorOffset) {
  std::mt19937 rng(11);
  const auto model = std::make_shared<const AnalyticViewpointClassifier>(0.4, 15.0);
  const SE2 mount(0.3, -0.1, 0.2);
  for (int trial = 0; trial < 40; ++trial) {
    const int c = trial % 2;
    Values values;
    values.insert(poseKey(0), randomPose(rng, 4.0));
    values.insert(landmarkKey(0), randomPose(rng, 4.0));
    Vector z(2);
    z << uniform01(rng), uniform01(rng);
    const ViewpointSemanticFactor<SE2> factor(poseKey(0), landmarkKey(0), z, c, model, mount);
    expectJacobiansMatch(factor, values, 1e-6);
  }
}

TEST(ViewpointSemanticFactor, JacobiansMatchForATabulatedModel) {
  std::mt19937 rng(5);
  const AnalyticViewpointClassifier analytic(0.3, 10.0);
  const auto table = std::make_shared<const TabulatedViewpointClassifier>(
      TabulatedViewpointClassifier::tabulate(analytic, 72));
  for (int trial = 0; trial < 20; ++trial) {
    Values values;
    values.insert(poseKey(0), randomPose(rng, 4.0));
    values.insert(landmarkKey(0), randomPose(rng, 4.0));
    Vector z(2);
    z << 0.6, 0.4;
    const ViewpointSemanticFactor<SE2> factor(poseKey(0), landmarkKey(0), z, trial % 2, table);
    // Piecewise linear: finite differences are exact away from the sample angles.
    expectJacobiansMatch(factor, values, 1e-4);
  }
}

TEST(ViewpointSemanticFactor, DensityIsTheClassifierModelsLikelihood) {
  std::mt19937 rng(3);
  const auto model = std::make_shared<const AnalyticViewpointClassifier>(0.25, 15.0);
  for (int trial = 0; trial < 10; ++trial) {
    const SE2 robot = randomPose(rng, 5.0), object = randomPose(rng, 5.0);
    Values values;
    values.insert(poseKey(0), robot);
    values.insert(landmarkKey(0), object);
    Vector z(2);
    z << uniform01(rng), uniform01(rng);
    const ViewpointSemanticFactor<SE2> factor(poseKey(0), landmarkKey(0), z, trial % 2, model);
    const double theta = viewpointAngle(robot, object);
    EXPECT_NEAR(-0.5 * factor.chi2(values) - *factor.logNormalizer(), model->logLikelihood(z, trial % 2, theta), 1e-9);
  }
}

TEST(ViewpointSemanticFactor, RejectsBadClassesAndMeasurements) {
  const auto model = std::make_shared<const AnalyticViewpointClassifier>();
  EXPECT_THROW(ViewpointSemanticFactor<SE2>(poseKey(0), landmarkKey(0), Vector::Zero(2), 2, model),
               std::invalid_argument);
  EXPECT_THROW(ViewpointSemanticFactor<SE2>(poseKey(0), landmarkKey(0), Vector::Zero(3), 0, model),
               std::invalid_argument);
  EXPECT_THROW(ViewpointSemanticFactor<SE2>(poseKey(0), landmarkKey(0), Vector::Zero(2), 0, nullptr),
               std::invalid_argument);
}
