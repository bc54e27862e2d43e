// APE, RPE, pose relations and alignment on small synthetic trajectories with known answers.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "semslam/eval/AbsolutePoseError.h"
#include "semslam/eval/Alignment.h"
#include "semslam/eval/PoseRelation.h"
#include "semslam/eval/RelativePoseError.h"
#include "semslam/eval/TrajectoryEvaluation.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

SE3 pose(double yaw, double x, double y, double z) {
  return SE3(SO3::fromAxisAngle(Vector3::UnitZ(), yaw), Point3(x, y, z));
}

/// A curved, non-planar trajectory with timestamps 0, 0.1, 0.2, ...
Trajectory curve(int n) {
  std::vector<double> stamps;
  std::vector<SE3> poses;
  for (int i = 0; i < n; ++i) {
    const double s = 0.3 * i;
    stamps.push_back(0.1 * i);
    poses.push_back(SE3(SO3::fromAxisAngle(Vector3(0.1, 0.2, 1.0), s), Point3(std::cos(s) * 5, std::sin(s) * 3, 0.2 * s * s)));
  }
  return Trajectory(stamps, poses);
}

TEST(PoseRelation, RotationAngleIsAccurateFromTinyToHalfTurn) {
  for (const double angle : {0.0, 1e-9, 1e-5, 0.3, 2.0, 3.0, std::numbers::pi - 1e-7, std::numbers::pi}) {
    const Matrix3 r = SO3::fromAxisAngle(Vector3(1, -2, 0.5), angle).matrix();
    EXPECT_NEAR(rotationAngle(r), angle, 1e-15 + 1e-12 * angle) << angle;
  }
  Matrix4 e = Matrix4::Identity();
  e.block<3, 3>(0, 0) = SO3::fromAxisAngle(Vector3::UnitX(), 0.5).matrix();
  e.block<3, 1>(0, 3) = Vector3(3, 4, 0);
  EXPECT_DOUBLE_EQ(poseErrorValue(e, PoseRelation::TranslationPart), 5.0);
  EXPECT_NEAR(poseErrorValue(e, PoseRelation::AngleRad), 0.5, 1e-15);
  EXPECT_NEAR(poseErrorValue(e, PoseRelation::AngleDeg), 0.5 * 180.0 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(poseErrorValue(e, PoseRelation::RotationPart), std::sqrt(2 * (2 - 2 * std::cos(0.5))), 1e-15);
  EXPECT_NEAR(poseErrorValue(e, PoseRelation::Full), std::sqrt(2 * (2 - 2 * std::cos(0.5)) + 25.0), 1e-14);
  EXPECT_THROW(parsePoseRelation("trans"), InputError);
}

TEST(AbsolutePoseError, TranslationAndAngleOfKnownOffsets) {
  const Trajectory ref(std::vector<double>{0, 1}, std::vector<SE3>{pose(0, 0, 0, 0), pose(0, 1, 0, 0)});
  const Trajectory est(std::vector<double>{0, 1}, std::vector<SE3>{pose(0.1, 0, 3, 4), pose(-0.2, 1, 0, 0)});
  const std::vector<double> t = absolutePoseErrors(ref, est);
  EXPECT_DOUBLE_EQ(t[0], 5.0);
  EXPECT_DOUBLE_EQ(t[1], 0.0);
  const std::vector<double> a = absolutePoseErrors(ref, est, PoseRelation::AngleRad);
  EXPECT_NEAR(a[0], 0.1, 1e-15);
  EXPECT_NEAR(a[1], 0.2, 1e-15);
  EXPECT_THROW(absolutePoseErrors(ref, Trajectory()), InputError);
}

TEST(RelativePoseError, IsBlindToAGlobalTransformAndSeesLocalDrift) {
  const Trajectory ref = curve(40);
  Trajectory moved = ref;
  moved.transform(pose(0.7, 10, -3, 2));
  RelativePoseErrorOptions options;
  const RelativePoseErrors same = relativePoseErrors(ref, moved, options);
  EXPECT_EQ(same.pairs.size(), 39u);
  for (const double e : same.errors) EXPECT_LT(e, 1e-12);
  options.relation = PoseRelation::AngleDeg;
  for (const double e : relativePoseErrors(ref, moved, options).errors) EXPECT_LT(e, 1e-9);

  // A 1 cm error in one relative motion shows up only in the pairs spanning it.
  std::vector<SE3> poses = ref.poses();
  for (std::size_t i = 20; i < poses.size(); ++i) poses[i] = SE3(poses[i].rotation(), poses[i].translation() + Vector3(0.01, 0, 0));
  const Trajectory drifted(ref.timestamps(), poses);
  options.relation = PoseRelation::TranslationPart;
  const RelativePoseErrors d = relativePoseErrors(ref, drifted, options);
  for (std::size_t k = 0; k < d.pairs.size(); ++k) {
    if (d.pairs[k].first == 19) EXPECT_NEAR(d.errors[k], 0.01, 1e-12);
    else EXPECT_LT(d.errors[k], 1e-12);
  }
}

TEST(RelativePoseError, PairsComeFromTheEstimateUnlessAskedOtherwise) {
  const Trajectory ref = curve(30);
  Trajectory doubled = ref;
  doubled.scale(2.0);  // twice the path length: pairs by metres differ between the two
  RelativePoseErrorOptions options;
  options.delta = 3.0;
  options.unit = DeltaUnit::Meters;
  const auto fromEstimate = relativePoseErrors(ref, doubled, options).pairs;
  EXPECT_EQ(fromEstimate, selectPosePairs(doubled, 3.0, DeltaUnit::Meters));
  options.pairsFromReference = true;
  EXPECT_EQ(relativePoseErrors(ref, doubled, options).pairs, selectPosePairs(ref, 3.0, DeltaUnit::Meters));
  EXPECT_NE(fromEstimate.size(), selectPosePairs(ref, 3.0, DeltaUnit::Meters).size());
}

TEST(Alignment, Se3Sim3ScaleAndOriginUndoKnownTransforms) {
  const Trajectory ref = curve(25);
  const SE3 g = pose(1.1, -4, 2, 0.5);
  {
    Trajectory est = ref;
    est.transform(g.inverse());
    const SimilarityTransform s = alignTrajectory(est, ref, AlignmentMode::Se3);
    EXPECT_LT((s.rotation - g.rotation().matrix()).cwiseAbs().maxCoeff(), 1e-12);
    for (const double e : absolutePoseErrors(ref, est)) EXPECT_LT(e, 1e-12);
    for (const double e : absolutePoseErrors(ref, est, PoseRelation::AngleRad)) EXPECT_LT(e, 1e-7);
  }
  {
    Trajectory est = ref;
    est.transform(g);
    est.scale(0.5);
    const SimilarityTransform s = alignTrajectory(est, ref, AlignmentMode::Sim3);
    EXPECT_NEAR(s.scale, 2.0, 1e-12);
    for (const double e : absolutePoseErrors(ref, est)) EXPECT_LT(e, 1e-11);
  }
  {
    Trajectory est = ref;
    est.scale(0.25);
    const SimilarityTransform s = alignTrajectory(est, ref, AlignmentMode::Scale);
    EXPECT_NEAR(s.scale, 4.0, 1e-12);
    EXPECT_EQ(s.rotation, Matrix3::Identity());
    for (const double e : absolutePoseErrors(ref, est)) EXPECT_LT(e, 1e-12);
  }
  {
    Trajectory est = ref;
    est.transform(g);
    alignTrajectory(est, ref, AlignmentMode::Origin);
    EXPECT_LT((est.pose(0).matrix() - ref.pose(0).matrix()).cwiseAbs().maxCoeff(), 1e-14);
    for (const double e : absolutePoseErrors(ref, est)) EXPECT_LT(e, 1e-12);
  }
  Trajectory est = ref;
  EXPECT_THROW(alignTrajectory(est, curve(3), AlignmentMode::Se3), InputError);
  EXPECT_THROW(parseAlignmentMode("sim(3)"), InputError);
}

TEST(TrajectoryEvaluation, AssociatesAlignsAndSummarises) {
  const Trajectory ref = curve(50);
  // The estimate: every other pose, timestamps off by 3 ms, in another frame.
  std::vector<double> stamps;
  std::vector<SE3> poses;
  const SE3 g = pose(-0.4, 1, 2, 3);
  for (std::size_t i = 0; i < ref.size(); i += 2) {
    stamps.push_back(ref.timestamp(i) + 0.003);
    poses.push_back(g * ref.pose(i));
  }
  const Trajectory est(stamps, poses);
  EvaluationOptions options;
  options.alignment = AlignmentMode::Se3;
  const EvaluationResult ape = evaluateAbsolutePoseError(ref, est, options);
  EXPECT_EQ(ape.associatedPoses, 25u);
  EXPECT_EQ(ape.statistics.count, 25u);
  EXPECT_LT(ape.statistics.max, 1e-12);
  options.alignment = AlignmentMode::None;
  EXPECT_GT(evaluateAbsolutePoseError(ref, est, options).statistics.min, 1.0);
  const EvaluationResult rpe = evaluateRelativePoseError(ref, est, options);  // RPE needs no alignment
  EXPECT_EQ(rpe.statistics.count, 24u);
  EXPECT_LT(rpe.statistics.max, 1e-12);
  options.maxTimeDifference = 0.002;
  EXPECT_THROW(evaluateAbsolutePoseError(ref, est, options), InputError);
}

}  // namespace
}  // namespace semslam
