// The association ceiling (run/KnownTrajectoryCeiling.h): the pinned log reproduces the trajectory it is pinned to,
// pose errors are drawn with the covariance asked for, and a method on the pinned log keeps the known-DA poses.

#include <gtest/gtest.h>

#include <random>

#include "semslam/geometry/Manifold.h"
#include "semslam/models/Sampling.h"
#include "semslam/run/KnownTrajectoryCeiling.h"
#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"

using namespace semslam;

namespace {

MeasurementLog simulatedRun(int dimension) {
  PathOptions path;
  path.dimension = dimension;
  path.steps = 60;
  path.loops = 1;
  std::mt19937 rng(5);
  SemanticSimOptions options;
  options.classes = 3;
  options.landmarks = 10;
  options.clutter = 0.3;
  options.misclassification = 0.1;
  options.fieldOfView = 0.0;
  return simulateSemantic(generatePath(path, rng), options, 5);
}

/// `method` with neither a run folder nor pose covariances (what these tests do not look at).
MethodOptions withoutExtras(Method method) {
  MethodOptions options;
  options.method = method;
  options.runFolder = false;
  options.poseCovariances = false;
  return options;
}

/// Largest tangent distance between two trajectories of one kind.
double largestDifference(const std::vector<Pose>& a, const std::vector<Pose>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Vector d = std::visit(
        [&](const auto& pose) -> Vector {
          using T = std::decay_t<decltype(pose)>;
          return Manifold<T>::local(pose, std::get<T>(b[k]));
        },
        a[k]);
    worst = std::max(worst, d.cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace

TEST(KnownTrajectoryCeiling, ThePinnedOdometryComposesBackToTheTrajectory) {
  for (int dimension : {2, 3}) {
    const MeasurementLog log = simulatedRun(dimension);
    std::vector<Pose> trajectory;
    for (const TimeStep& step : log.steps) trajectory.push_back(*step.truePose);
    const MeasurementLog pinned = logOnTrajectory(log, trajectory);
    ASSERT_TRUE(pinned.header.initialPose.has_value());
    std::vector<Pose> composed = {pinned.header.initialPose->mean};
    for (std::size_t k = 1; k < pinned.steps.size(); ++k) {
      const Pose& increment = pinned.steps[k].odometry->increment;
      composed.push_back(std::visit(
          [&](const auto& previous) -> Pose {
            using T = std::decay_t<decltype(previous)>;
            return previous.compose(std::get<T>(increment));
          },
          composed.back()));
      EXPECT_DOUBLE_EQ(pinned.steps[k].odometry->covariance(0, 0), kPinnedSigma * kPinnedSigma);
    }
    EXPECT_LT(largestDifference(composed, trajectory), 1e-9) << dimension << "D";
    EXPECT_EQ(pinned.steps.size(), log.steps.size());
    EXPECT_EQ(pinned.steps[7].detections.size(), log.steps[7].detections.size());
    EXPECT_THROW(logOnTrajectory(log, {trajectory.front()}), std::invalid_argument);
  }
}

TEST(KnownTrajectoryCeiling, PoseErrorsHaveTheScaledCovariance) {
  const Matrix covariance = (Matrix(3, 3) << 0.04, 0.01, 0.0, 0.01, 0.09, 0.002, 0.0, 0.002, 0.01).finished();
  const std::vector<Pose> trajectory(4000, Pose(SE2(1.0, 2.0, 0.3)));
  const std::vector<Matrix> covariances(trajectory.size(), covariance);
  EXPECT_EQ(largestDifference(perturbedTrajectory(trajectory, covariances, 0.0, 1), trajectory), 0.0);
  const double scale = 0.5;
  const std::vector<Pose> moved = perturbedTrajectory(trajectory, covariances, scale, 3);
  Matrix sample = Matrix::Zero(3, 3);
  for (const Pose& pose : moved) {
    const Vector d = Manifold<SE2>::local(std::get<SE2>(trajectory.front()), std::get<SE2>(pose));
    sample += d * d.transpose();
  }
  sample /= static_cast<double>(moved.size());
  const Matrix expected = scale * scale * covariance;
  // Sample variances of 4000 draws: relative standard error sqrt(2 / 4000) ≈ 2.2 %; 5 standard errors.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(sample(i, i) / expected(i, i), 1.0, 0.11) << i;
  EXPECT_NEAR(sample(0, 1), expected(0, 1), 0.11 * std::sqrt(expected(0, 0) * expected(1, 1)));
  EXPECT_EQ(largestDifference(perturbedTrajectory(trajectory, covariances, scale, 3), moved), 0.0);  // seeded
}

TEST(KnownTrajectoryCeiling, AMethodOnThePinnedLogKeepsTheKnownAssociationTrajectory) {
  const MeasurementLog log = simulatedRun(2);
  const MethodRun reference = runMethod(log, withoutExtras(Method::Known));
  MethodOptions options = withoutExtras(Method::MaxMixtureNullHypothesis);
  options.slam.birth = BirthRule::Unassigned;
  const MethodRun ceiling = runOnKnownTrajectory(log, options, 0.0, 1);
  EXPECT_EQ(ceiling.result.method, "mm-nh@known-trajectory");
  EXPECT_EQ(ceiling.evaluation.metrics.method, ceiling.result.method);
  // Pinned at σ = 1e-4 per step beside detections of σ ≈ 0.1: the poses move by well under a millimetre.
  EXPECT_LT(largestDifference(ceiling.result.poses, reference.result.poses), 1e-3);
  // The method's own options that `known` refuses (branches, open splits, switch rounds) go to the method, not the
  // reference.
  MethodOptions branched = options;
  branched.slam.loopClosureBranchWindow = 8;
  branched.slam.loopClosureNextBest = true;
  branched.slam.loopClosureOpenSplits = 2;
  branched.switchRounds = 2;
  EXPECT_EQ(runOnKnownTrajectory(log, branched, 0.0, 1).result.method, "mm-nh@known-trajectory");
  branched.slam.loopClosureBranchWindow = 0;  // the method's refusals still hold
  EXPECT_THROW(runOnKnownTrajectory(log, branched, 0.0, 1), std::invalid_argument);
  options.method = Method::Hybrid;
  EXPECT_THROW(runOnKnownTrajectory(log, options, 0.0, 1), std::invalid_argument);
}

namespace {

/// Mean over k of ‖(x_k⁻¹ x_{k+1}) ⊖ (y_k⁻¹ y_{k+1})‖: how far two trajectories' consecutive motions differ.
double meanRelativeDifference(const std::vector<Pose>& a, const std::vector<Pose>& b) {
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < a.size(); ++k) {
    const SE2 motionA = std::get<SE2>(a[k]).between(std::get<SE2>(a[k + 1]));
    const SE2 motionB = std::get<SE2>(b[k]).between(std::get<SE2>(b[k + 1]));
    sum += Manifold<SE2>::local(motionA, motionB).norm();
  }
  return sum / static_cast<double>(a.size() - 1);
}

}  // namespace

TEST(KnownTrajectoryCeiling, AJointPoseErrorKeepsTheEstimatesRelativeErrorsWhereIndependentOnesDoNot) {
  const MeasurementLog log = simulatedRun(2);
  const MethodOptions options = withoutExtras(Method::Known);
  const MethodRun reference = runMethod(log, options);
  const MethodRun joint = runOnKnownTrajectory(log, options, 1.0, 7, PoseErrorDraw::Joint);
  const MethodRun independent = runOnKnownTrajectory(log, options, 1.0, 7, PoseErrorDraw::Independent);
  // Both move the poses by about their marginal σ (the known-association estimate's: centimetres here) ...
  EXPECT_GT(largestDifference(joint.result.poses, reference.result.poses), 1e-3);
  EXPECT_GT(largestDifference(independent.result.poses, reference.result.poses), 1e-3);
  // ... but only the independent draw gives neighbouring poses independent errors: between consecutive poses the
  // joint draw differs from the estimate by the posterior's relative uncertainty, a fraction of the marginal one.
  const double jointRelative = meanRelativeDifference(joint.result.poses, reference.result.poses);
  const double independentRelative = meanRelativeDifference(independent.result.poses, reference.result.poses);
  EXPECT_LT(jointRelative, 0.5 * independentRelative) << jointRelative << " against " << independentRelative;
  // Seeded: the same draw again.
  const MethodRun again = runOnKnownTrajectory(log, options, 1.0, 7, PoseErrorDraw::Joint);
  EXPECT_EQ(largestDifference(again.result.poses, joint.result.poses), 0.0);
  EXPECT_THROW(runOnKnownTrajectory(log, options, -1.0, 7), std::invalid_argument);
}
