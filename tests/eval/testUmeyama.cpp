// Umeyama alignment recovers a known similarity / rigid transform exactly (to rounding) on noise-free points.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "semslam/eval/Umeyama.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

Matrix3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

Eigen::Matrix3Xd randomPoints(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> uniform(-20.0, 20.0);
  Eigen::Matrix3Xd x(3, n);
  for (int i = 0; i < n; ++i) x.col(i) = Vector3(uniform(rng), uniform(rng), uniform(rng));
  return x;
}

TEST(Umeyama, RecoversRandomSim3Exactly) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> scaleDist(0.2, 5.0), offset(-100.0, 100.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Matrix3 r = randomRotation(rng);
    const Vector3 t(offset(rng), offset(rng), offset(rng));
    const double c = scaleDist(rng);
    const Eigen::Matrix3Xd x = randomPoints(rng, 3 + trial * 7);
    const Eigen::Matrix3Xd y = ((c * r) * x).colwise() + t;
    const SimilarityTransform s = umeyamaAlignment(x, y, true);
    EXPECT_LT((s.rotation - r).cwiseAbs().maxCoeff(), 1e-12) << trial;
    EXPECT_LT((s.translation - t).cwiseAbs().maxCoeff(), 1e-10) << trial;
    EXPECT_NEAR(s.scale, c, 1e-12) << trial;
    EXPECT_NEAR(s.rotation.determinant(), 1.0, 1e-12);
  }
}

TEST(Umeyama, RecoversRandomSE3ExactlyWithoutScale) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> offset(-10.0, 10.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Matrix3 r = randomRotation(rng);
    const Vector3 t(offset(rng), offset(rng), offset(rng));
    const Eigen::Matrix3Xd x = randomPoints(rng, 50);
    const Eigen::Matrix3Xd y = (r * x).colwise() + t;
    const SimilarityTransform s = umeyamaAlignment(x, y, false);
    EXPECT_DOUBLE_EQ(s.scale, 1.0);
    EXPECT_LT((s.rotation - r).cwiseAbs().maxCoeff(), 1e-12) << trial;
    EXPECT_LT((s.translation - t).cwiseAbs().maxCoeff(), 1e-11) << trial;
  }
}

TEST(Umeyama, PlanarPointsStillGiveAProperRotation) {
  // Points in a plane make the smallest singular value 0; the det correction must keep R a rotation.
  std::mt19937 rng(11);
  Eigen::Matrix3Xd x = randomPoints(rng, 30);
  x.row(2).setZero();
  const Matrix3 r = randomRotation(rng);
  const Vector3 t(1.0, -2.0, 3.0);
  const Eigen::Matrix3Xd y = (r * x).colwise() + t;
  const SimilarityTransform s = umeyamaAlignment(x, y, false);
  EXPECT_NEAR(s.rotation.determinant(), 1.0, 1e-12);
  EXPECT_LT((s.rotation - r).cwiseAbs().maxCoeff(), 1e-10);
  for (int i = 0; i < x.cols(); ++i) EXPECT_LT((s.apply(x.col(i)) - y.col(i)).norm(), 1e-10);
}

TEST(Umeyama, MirroredPointsGiveTheBestRotationNotAReflection) {
  std::mt19937 rng(5);
  const Eigen::Matrix3Xd x = randomPoints(rng, 40);
  Eigen::Matrix3Xd y = x;
  y.row(0) *= -1.0;  // a reflection: no rotation maps x onto y
  const SimilarityTransform s = umeyamaAlignment(x, y, true);
  EXPECT_NEAR(s.rotation.determinant(), 1.0, 1e-12);
  EXPECT_LT((s.rotation.transpose() * s.rotation - Matrix3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Umeyama, DegenerateInputsThrow) {
  Eigen::Matrix3Xd line(3, 5);
  for (int i = 0; i < 5; ++i) line.col(i) = Vector3(i, 2.0 * i, -i);
  EXPECT_THROW(umeyamaAlignment(line, line, false), InputError);
  const Eigen::Matrix3Xd single = Eigen::Matrix3Xd::Ones(3, 1);
  EXPECT_THROW(umeyamaAlignment(single, single, true), InputError);
  EXPECT_THROW(umeyamaAlignment(Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xd(3, 0), false), InputError);
  EXPECT_THROW(umeyamaAlignment(Eigen::Matrix3Xd::Random(3, 4), Eigen::Matrix3Xd::Random(3, 5), false), InputError);
}

}  // namespace
}  // namespace semslam
