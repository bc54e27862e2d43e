// The sparse normal equations equal the dense JᵀJ and Jᵀr built from the stacked factor Jacobians.

#include <gtest/gtest.h>

#include "SmallProblems.h"
#include "semslam/solve/NormalEquations.h"

using namespace semslam;

TEST(NormalEquations, MatchesDenseStackedJacobian) {
  const test::Problem problem = test::planarSlamProblem();
  NormalEquations system(problem.graph, problem.initial);
  const double chi2 = system.assemble(problem.initial);

  // Dense J and r, stacked factor by factor, columns at the system's offsets.
  int rows = 0;
  for (const auto& factor : problem.graph) rows += factor->errorDimension();
  Matrix J = Matrix::Zero(rows, system.dimension());
  Vector r(rows);
  int row = 0;
  LinearizedFactor lin;
  for (const auto& factor : problem.graph) {
    factor->linearize(problem.initial, lin);
    const int d = factor->errorDimension();
    r.segment(row, d) = lin.whitenedError;
    for (std::size_t k = 0; k < factor->keys().size(); ++k) {
      const Key key = factor->keys()[k];
      J.block(row, system.offset(key), d, system.dimension(key)) = lin.jacobians[k];
    }
    row += d;
  }
  const Matrix expectedH = J.transpose() * J;
  const Matrix upper = Matrix(system.hessian());
  const Matrix H = Matrix(upper.selfadjointView<Eigen::Upper>());
  EXPECT_LE((H - expectedH).cwiseAbs().maxCoeff(), 1e-9 * expectedH.cwiseAbs().maxCoeff());
  EXPECT_TRUE(upper.isUpperTriangular(0.0));
  EXPECT_TRUE(system.gradient().isApprox(J.transpose() * r, 1e-12));
  EXPECT_NEAR(chi2, r.squaredNorm(), 1e-9 * chi2);
  EXPECT_NEAR(chi2, problem.graph.chi2(problem.initial), 1e-9 * chi2);
  for (int c = 0; c < system.dimension(); ++c) {
    EXPECT_NEAR(system.hessian().valuePtr()[system.diagonalPositions()[c]], expectedH(c, c),
                1e-9 * expectedH.cwiseAbs().maxCoeff());
  }
}

TEST(NormalEquations, ReassemblyGivesTheSameNumbers) {
  const test::Problem problem = test::planarSlamProblem();
  NormalEquations system(problem.graph, problem.initial);
  system.assemble(problem.initial);
  const Matrix first = Matrix(system.hessian());
  system.assemble(problem.initial);
  EXPECT_EQ((Matrix(system.hessian()) - first).cwiseAbs().maxCoeff(), 0.0);
}

TEST(NormalEquations, RejectsFactorsOnMissingVariables) {
  test::Problem problem = test::planarSlamProblem();
  problem.graph.emplace<PriorFactor<SE2>>(poseKey(999), SE2(), NoiseModel::isotropic(3, 1.0));
  EXPECT_THROW(NormalEquations(problem.graph, problem.initial), std::invalid_argument);
}

TEST(NormalEquations, RetractMovesEveryVariableByItsBlock) {
  const test::Problem problem = test::planarSlamProblem();
  NormalEquations system(problem.graph, problem.initial);
  Vector delta = Vector::Zero(system.dimension());
  delta.segment(system.offset(poseKey(3)), 3) = Vector3(0.1, 0.2, 0.3);
  delta.segment(system.offset(landmarkKey(1)), 2) = Vector2(-1.0, 1.0);
  const Values moved = system.retract(problem.initial, delta);
  EXPECT_TRUE(moved.at<SE2>(poseKey(3)).equals(problem.initial.at<SE2>(poseKey(3)).retract(Vector3(0.1, 0.2, 0.3))));
  EXPECT_TRUE(moved.at<Point2>(landmarkKey(1)).isApprox(problem.initial.at<Point2>(landmarkKey(1)) + Vector2(-1, 1)));
  EXPECT_TRUE(moved.at<SE2>(poseKey(4)).equals(problem.initial.at<SE2>(poseKey(4)), 0.0));
}
