// CartesianGateFactor: Jacobians, and agreement with the range-bearing measurement it re-expresses.

#include <gtest/gtest.h>

#include <random>

#include "semslam/hybrid/CartesianGateFactor.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/Sampling.h"
#include "support/FactorTesting.h"

using namespace semslam;

TEST(CartesianGateFactor, JacobiansAndZeroErrorAtTheMeasuredPoint) {
  std::mt19937 rng(2);
  const SE2 mount(0.2, 0.1, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    const SE2 robot(4 * uniform01(rng) - 2, 4 * uniform01(rng) - 2, 6 * uniform01(rng) - 3);
    const SE2 object(4 * uniform01(rng) - 2, 4 * uniform01(rng) - 2, 6 * uniform01(rng) - 3);
    const Vector2 rb = RangeBearingSensor2(mount).predict(robot, object.translation());
    const auto factor = CartesianGateFactor<SE2>::fromRangeBearing(poseKey(0), landmarkKey(0), rb,
                                                                  Vector2(0.1, 0.05).asDiagonal(), mount);
    Values values;
    values.insert(poseKey(0), robot);
    values.insert(landmarkKey(0), object);
    EXPECT_NEAR(factor->chi2(values), 0.0, 1e-16);
    values.update(landmarkKey(0), SE2(object.rotation(), object.translation() + Point2(0.3, -0.2)));
    test::expectJacobiansMatch(*factor, values, 1e-6);
  }
}
