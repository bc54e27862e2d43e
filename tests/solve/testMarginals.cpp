// Marginal covariances from the sparse factor equal blocks of the dense inverse of the information matrix.

#include <gtest/gtest.h>

#include <Eigen/LU>

#include "SmallProblems.h"
#include "semslam/solve/BatchSmoother.h"
#include "semslam/solve/IncrementalSmoother.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/NormalEquations.h"
#include "semslam/solve/Optimizer.h"

using namespace semslam;

TEST(Marginals, EqualBlocksOfTheDenseInverse) {
  const test::Problem problem = test::planarSlamProblem(10, 4, 8);
  const Values optimum = optimize(problem.graph, problem.initial).values;
  NormalEquations system(problem.graph, optimum);
  system.assemble(optimum);
  const Matrix H = Matrix(Matrix(system.hessian()).selfadjointView<Eigen::Upper>());
  const Matrix covariance = H.inverse();

  const Marginals marginals(problem.graph, optimum);
  for (Key key : system.keys()) {
    const int o = system.offset(key), d = system.dimension(key);
    const Matrix expected = covariance.block(o, o, d, d);
    EXPECT_LE((marginals.marginalCovariance(key) - expected).cwiseAbs().maxCoeff(),
              1e-10 * expected.cwiseAbs().maxCoeff())
        << keyToString(key);
  }
  // A joint marginal in request order, with cross-covariances.
  const std::vector<Key> keys = {landmarkKey(2), poseKey(7), poseKey(0)};
  const JointMarginal joint = marginals.jointMarginal(keys);
  ASSERT_EQ(joint.covariance().rows(), 8);
  for (Key a : keys) {
    for (Key b : keys) {
      const Matrix expected = covariance.block(system.offset(a), system.offset(b), system.dimension(a),
                                               system.dimension(b));
      EXPECT_LE((joint.block(a, b) - expected).cwiseAbs().maxCoeff(), 1e-10 * covariance.cwiseAbs().maxCoeff());
    }
  }
  EXPECT_THROW(joint.block(poseKey(3), poseKey(3)), std::out_of_range);
  EXPECT_THROW(marginals.jointMarginal({poseKey(1), poseKey(1)}), std::invalid_argument);
}

TEST(Marginals, OfAnEmptyGraphAreRefusedNotACrash) {
  // Found through the Python module: a batch smoother updated with nothing, then asked for a marginal.
  EXPECT_THROW(Marginals(FactorGraph(), Values()), std::invalid_argument);
  BatchSmoother smoother;
  smoother.update();
  EXPECT_THROW(smoother.jointMarginal({poseKey(0)}), std::invalid_argument);
}

TEST(Marginals, OfNoKeysAreEmptyInEverySmoother) {
  // Found through the Python module: the batch smoother's Cholesky solve of zero columns failed, where the
  // incremental smoother gives the 0 × 0 marginal.
  const test::Problem problem = test::planarSlamProblem(4, 2, 3);
  BatchSmoother batch;
  batch.update(problem.graph, problem.initial);
  EXPECT_EQ(batch.jointMarginal({}).covariance().size(), 0);
  IncrementalSmoother incremental;
  incremental.update(problem.graph, problem.initial);
  EXPECT_EQ(incremental.jointMarginal({}).covariance().size(), 0);
}
