// The odometry's consistency over windows of n steps (eval/MeasurementResiduals.h): true poses made from the
// odometry with noise drawn from its stated covariance give a mean NEES of d at every window length (which fails if
// the covariance is composed without the adjoint, or with the wrong one); a constant heading bias far below a step's
// σ shows in the long windows only; exact odometry gives 0; steps without a true pose or odometry are left out.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "semslam/eval/MeasurementResiduals.h"
#include "semslam/models/Sampling.h"

namespace semslam {
namespace {

constexpr int kSteps = 3000;

LogHeader header(int dimension) {
  LogHeader h;
  h.dimension = dimension;
  h.sensor.kind = SensorKind::RelativePosition;
  return h;
}

// A 2D log turning and driving: the increments vary, so a wrong adjoint shows. Each true step is the increment
// perturbed on the right by ε ~ N(bias, Σ).
MeasurementLog planarLog(double headingBias, bool noise, std::uint32_t seed) {
  MeasurementLog log;
  log.header = header(2);
  std::mt19937 rng(seed);
  Matrix covariance = Matrix::Zero(3, 3);
  // σ_θ = 0.01 rad: 0.1 rad over 100 steps, where the first-order propagation still holds (at 0.3 rad the
  // fraction inside the quantile falls to 0.91 from the banana-shaped position error, not from the composition).
  covariance.diagonal() << 0.02 * 0.02, 0.005 * 0.005, 0.01 * 0.01;
  covariance(0, 2) = covariance(2, 0) = 0.3 * 0.02 * 0.01;  // correlated x and θ
  SE2 truth;
  for (int k = 0; k < kSteps; ++k) {
    TimeStep step;
    step.time = k;
    if (k > 0) {
      const SE2 increment(0.5 + 0.3 * std::sin(0.05 * k), 0.02, 0.2 * std::cos(0.03 * k));
      Vector3 error = Vector3(0.0, 0.0, headingBias);
      if (noise) error += sampleGaussian(Vector3::Zero(), covariance, rng);
      truth = truth.compose(increment.compose(SE2::Exp(error)));
      step.odometry = Odometry{increment, covariance};
    }
    step.truePose = truth;
    log.steps.push_back(step);
  }
  return log;
}

TEST(OdometryWindows, NoiseAsStatedGivesAMeanNeesOfTheDimensionAtEveryWindow) {
  const LogResidualStatistics s = computeResidualStatistics(planarLog(0.0, true, 7));
  ASSERT_EQ(s.odometryWindows.size(), kOdometryWindowSteps.size());
  for (const OdometryWindowStatistics& w : s.odometryWindows) {
    EXPECT_EQ(w.dimension, 3);
    EXPECT_EQ(w.windows, static_cast<std::size_t>(kSteps - w.steps)) << w.steps;
    // The windows overlap, so their NEES are correlated: the tolerance is wider than independent samples' would be.
    EXPECT_NEAR(w.meanNees, 3.0, w.steps == 100 ? 0.5 : 0.25) << w.steps;
    EXPECT_NEAR(w.withinQuantile, 0.95, 0.03) << w.steps;
  }
}

TEST(OdometryWindows, AHeadingBiasBelowAStepsSigmaShowsInTheLongWindowsOnly) {
  // 0.003 rad per step against σ_θ = 0.01: per step it adds (0.3)² / (1 − 0.3²) ≈ 0.1 to the mean NEES; over 100
  // steps the bias is 0.3 rad against σ ≈ 0.1 rad, about 9 in the heading alone.
  const LogResidualStatistics s = computeResidualStatistics(planarLog(0.003, true, 7));
  EXPECT_LT(s.odometryWindows[0].meanNees, 3.35);
  EXPECT_GT(s.odometryWindows[2].meanNees, 12.0);
  EXPECT_LT(s.odometryWindows[2].withinQuantile, 0.5);
}

TEST(OdometryWindows, ExactOdometryHasZeroNees) {
  for (const OdometryWindowStatistics& w : computeResidualStatistics(planarLog(0.0, false, 1)).odometryWindows) {
    EXPECT_NEAR(w.meanNees, 0.0, 1e-12) << w.steps;
    EXPECT_EQ(w.withinQuantile, 1.0);
  }
}

TEST(OdometryWindows, AWindowNeedsTruePosesAtItsEndsAndOdometryAtEveryStep) {
  MeasurementLog log = planarLog(0.0, false, 1);
  log.steps.resize(30);
  log.steps[12].truePose.reset();  // ends of windows 11→12 and 2→12 lost, and 12→13, 12→22
  log.steps[20].odometry.reset();  // windows through 19→20 lost: 19→20 and 10..19→20..29
  const LogResidualStatistics s = computeResidualStatistics(log);
  // n = 1: 29 windows, less 11→12, 12→13 (no true pose) and 19→20 (no odometry).
  EXPECT_EQ(s.odometryWindows[0].windows, 29u - 3u);
  // n = 10: 20 windows (start 0..19), less start 2 and 12 (true pose), and starts 10..19 cross step 20 (one of
  // them, 12, already counted).
  EXPECT_EQ(s.odometryWindows[1].windows, 20u - 2u - 9u);
  EXPECT_EQ(s.odometryWindows[2].windows, 0u);
  EXPECT_EQ(s.odometryWindows[2].meanNees, 0.0);
}

TEST(OdometryWindows, ThreeDimensionalOdometryUsesSixDegreesOfFreedom) {
  MeasurementLog log;
  log.header = header(3);
  std::mt19937 rng(3);
  Matrix covariance = Matrix::Identity(6, 6) * 1e-4;
  SE3 truth;
  for (int k = 0; k < kSteps; ++k) {
    TimeStep step;
    step.time = k;
    if (k > 0) {
      Vector6 twist;
      twist << 0.5, 0.0, 0.01, 0.01 * std::sin(0.1 * k), 0.0, 0.1 * std::cos(0.02 * k);
      const SE3 increment = SE3::Exp(twist);
      truth = truth.compose(increment.compose(SE3::Exp(sampleGaussian(Vector6::Zero(), covariance, rng))));
      step.odometry = Odometry{increment, covariance};
    }
    step.truePose = truth;
    log.steps.push_back(step);
  }
  for (const OdometryWindowStatistics& w : computeResidualStatistics(log).odometryWindows) {
    EXPECT_EQ(w.dimension, 6);
    EXPECT_NEAR(w.meanNees, 6.0, w.steps == 100 ? 0.8 : 0.4) << w.steps;
  }
}

}  // namespace
}  // namespace semslam
