// A system that cannot be solved is reported with the variables at fault and what would fix them
// (solve/UnconstrainedSystem.h), by the batch optimizer, the incremental smoother and the marginals alike.

#include <gtest/gtest.h>

#include <string>

#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/graph/NoiseModelFactor.h"
#include "semslam/solve/IncrementalSmoother.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/Optimizer.h"
#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam {
namespace {

SharedNoiseModel poseNoise() { return NoiseModel::fromSigmas(Vector3(0.1, 0.1, 0.05)); }

/// Observes only the x coordinate of a point: leaves its y free.
class XOnlyFactor : public NoiseModelFactor<1, Point2> {
 public:
  XOnlyFactor(Key key, double x) : NoiseModelFactor(NoiseModel::isotropic(1, 0.1), {key}), x_(x) {}
  ErrorVector evaluateError(const Point2& p, Jacobian<Point2>* H) const override {
    if (H) *H << 1.0, 0.0;
    return ErrorVector(p.x() - x_);
  }

 private:
  double x_;
};

/// x0 - x1 - x2 by odometry; a prior on x0 when `anchored`.
FactorGraph chain(bool anchored, Values& values) {
  FactorGraph graph;
  if (anchored) graph.emplace<PriorFactor<SE2>>(poseKey(0), SE2(), poseNoise());
  for (int i = 0; i < 2; ++i) {
    graph.emplace<BetweenFactor<SE2>>(poseKey(i), poseKey(i + 1), SE2(1, 0, 0), poseNoise());
  }
  for (int i = 0; i < 3; ++i) values.insert(poseKey(i), SE2(i * 1.1, 0.1, 0.0));
  return graph;
}

std::string failureOf(const FactorGraph& graph, const Values& values) {
  OptimizerParams params;
  params.solver = SolverType::GaussNewton;
  try {
    optimize(graph, values, params);
  } catch (const UnconstrainedSystemError& error) {
    return error.what();
  }
  return "no error";
}

TEST(UnconstrainedSystem, RelativeMeasurementsWithoutAPriorNameTheFreePartAndAskForAnAnchor) {
  Values values;
  const FactorGraph graph = chain(false, values);
  const std::string message = failureOf(graph, values);
  EXPECT_NE(message.find("nothing holds the 3 variables x0, x1, x2 in place"), std::string::npos) << message;
  EXPECT_NE(message.find("Add a prior (an anchor) on one of them"), std::string::npos) << message;
  EXPECT_EQ(message.find("CHOLMOD"), std::string::npos) << message;
}

TEST(UnconstrainedSystem, AVariableNoFactorNamesIsNamed) {
  Values values;
  const FactorGraph graph = chain(true, values);
  values.insert(landmarkKey(4), Point2(1, 2));
  const std::string message = describeUnconstrained(graph, values);
  EXPECT_NE(message.find("no factor names variable l4"), std::string::npos) << message;
}

TEST(UnconstrainedSystem, ASeparatePartWithoutAPriorIsNamed) {
  Values values;
  FactorGraph graph = chain(true, values);
  graph.emplace<BetweenFactor<SE2>>(poseKey(7), poseKey(8), SE2(1, 0, 0), poseNoise());
  values.insert(poseKey(7), SE2());
  values.insert(poseKey(8), SE2(1, 0, 0));
  const std::string message = failureOf(graph, values);
  EXPECT_NE(message.find("the 2 variables x7, x8"), std::string::npos) << message;
  EXPECT_EQ(message.find("x0"), std::string::npos) << message;
}

TEST(UnconstrainedSystem, AVariableItsFactorsDoNotFixIsNamedWithTheFreeDirections) {
  Values values;
  FactorGraph graph = chain(true, values);
  graph.emplace<XOnlyFactor>(landmarkKey(2), 3.0);
  values.insert(landmarkKey(2), Point2(2.5, 1.0));
  const std::string message = failureOf(graph, values);
  EXPECT_NE(message.find("variable l2 has 2 dimensions but its 1 factor fix only 1 of them"), std::string::npos)
      << message;
}

TEST(UnconstrainedSystem, TheIncrementalSmootherAndTheMarginalsGiveTheSameDescription) {
  Values values;
  const FactorGraph graph = chain(false, values);
  const std::string expected = describeUnconstrained(graph, values);
  IncrementalSmoother smoother;
  try {
    smoother.update(graph, values);
    ADD_FAILURE() << "the incremental smoother solved an unanchored chain";
  } catch (const UnconstrainedSystemError& error) {
    EXPECT_EQ(std::string(error.what()), expected);
  }
  try {
    Marginals marginals(graph, values);
    ADD_FAILURE() << "marginals of an unanchored chain";
  } catch (const UnconstrainedSystemError& error) {
    EXPECT_EQ(std::string(error.what()), expected);
  }
}

TEST(UnconstrainedSystem, AConstrainedSystemSolves) {
  Values values;
  const FactorGraph graph = chain(true, values);
  EXPECT_EQ(failureOf(graph, values), "no error");
}

}  // namespace
}  // namespace semslam
