// LogPerturbation: the added odometry noise has the stated covariance (Monte Carlo over seeds, 2D and 3D, with
// uneven step durations) and the log's covariance grows by exactly that; scale 0 leaves the log bit-identical;
// labels are redrawn at the confusion rate (binomial error), nested across rates, clutter uniform; the true class
// comes from the landmark truth or id mod M; the same seed gives the same log.

#include <gtest/gtest.h>

#include <cmath>

#include "semslam/study/LogPerturbation.h"
#include "study/StudyTesting.h"

namespace semslam {
namespace {

/// A log with `steps` odometry steps of uneven durations (0.5 s and 2 s alternating) and `detections` labelled
/// detections per step of landmarks 0..9 (class: id mod 3) plus one clutter detection.
MeasurementLog syntheticLog(int dimension, int steps, int detections = 0) {
  MeasurementLog log;
  log.header.dimension = dimension;
  log.header.classes = 3;
  log.header.semantic = SemanticKind::Label;
  log.header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  log.header.classifier.misclassification = 0.05;
  log.header.sensor.kind = SensorKind::RelativePosition;
  const int d = dimension == 2 ? 3 : 6;
  double time = 0.0;
  for (int k = 0; k <= steps; ++k) {
    TimeStep step;
    step.time = time;
    time += k % 2 == 0 ? 0.5 : 2.0;
    if (k > 0) {
      Odometry odometry;
      if (dimension == 2) {
        odometry.increment = SE2(1.0, 0.1, 0.2);
      } else {
        Vector6 xi;
        xi << 1.0, 0.1, 0.05, 0.02, -0.03, 0.2;
        odometry.increment = SE3::Exp(xi);
      }
      odometry.covariance = Matrix::Identity(d, d) * 1e-4;
      step.odometry = odometry;
    }
    for (int j = 0; j <= detections && detections > 0; ++j) {
      Detection detection;
      detection.geometry = Vector::Constant(dimension, 1.0);
      detection.covariance = Matrix::Identity(dimension, dimension) * 0.01;
      detection.label = 0;
      detection.truthId = j == detections ? kNotALandmark : (j + k) % 10;
      step.detections.push_back(detection);
    }
    log.steps.push_back(step);
  }
  return log;
}

Vector incrementError(const Pose& original, const Pose& perturbed) {
  if (std::holds_alternative<SE2>(original)) {
    return SE2::Log(std::get<SE2>(original).between(std::get<SE2>(perturbed)));
  }
  return SE3::Log(std::get<SE3>(original).between(std::get<SE3>(perturbed)));
}

void checkNoiseCovariance(int dimension) {
  const MeasurementLog log = syntheticLog(dimension, 2);
  const std::vector<double> dt = stepDurations(log);
  ASSERT_DOUBLE_EQ(dt[1], 0.5);
  ASSERT_DOUBLE_EQ(dt[2], 2.0);
  const double scale = 3.0;
  const int samples = 4000;
  const int d = dimension == 2 ? 3 : 6;
  for (int k = 1; k <= 2; ++k) {
    const Matrix q = addedOdometryCovariance(dimension, scale, dt[k]);
    Matrix sum = Matrix::Zero(d, d);
    Vector mean = Vector::Zero(d);
    for (int seed = 0; seed < samples; ++seed) {
      std::mt19937 rng = perturbationStream(seed, 1);
      const MeasurementLog noisy = addOdometryNoise(log, scale, rng);
      const Vector e = incrementError(log.steps[k].odometry->increment, noisy.steps[k].odometry->increment);
      sum += e * e.transpose();
      mean += e;
      // The log's covariance grows by exactly Q.
      ASSERT_TRUE((noisy.steps[k].odometry->covariance - log.steps[k].odometry->covariance - q).isZero(1e-15));
    }
    mean /= samples;
    const Matrix covariance = sum / samples;
    for (int i = 0; i < d; ++i) {
      EXPECT_NEAR(mean(i), 0.0, 5.0 * std::sqrt(q(i, i) / samples)) << "step " << k << " axis " << i;
      for (int j = 0; j < d; ++j) {
        const double standardError = std::sqrt((q(i, i) * q(j, j) + q(i, j) * q(i, j)) / samples);
        EXPECT_NEAR(covariance(i, j), q(i, j), 5.0 * standardError) << "step " << k << " (" << i << "," << j << ")";
      }
    }
  }
}

TEST(LogPerturbation, AddedCovarianceFollowsTheBaselinePerSecond) {
  const Matrix q2 = addedOdometryCovariance(2, 2.0, 0.5);
  EXPECT_DOUBLE_EQ(q2(0, 0), 0.04 * 0.04 * 0.5);
  EXPECT_DOUBLE_EQ(q2(1, 1), 0.04 * 0.04 * 0.5);
  EXPECT_DOUBLE_EQ(q2(2, 2), 0.02 * 0.02 * 0.5);
  EXPECT_EQ(q2(0, 1), 0.0);
  const Matrix q3 = addedOdometryCovariance(3, 1.0, 1.0);
  ASSERT_EQ(q3.rows(), 6);
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(q3(i, i), 0.02 * 0.02);
  for (int i = 3; i < 6; ++i) EXPECT_DOUBLE_EQ(q3(i, i), 0.01 * 0.01);
}

TEST(LogPerturbation, NoiseHasTheStatedCovariance2d) { checkNoiseCovariance(2); }
TEST(LogPerturbation, NoiseHasTheStatedCovariance3d) { checkNoiseCovariance(3); }

TEST(LogPerturbation, LogWithoutTimesUsesOneSecondSteps) {
  MeasurementLog log = syntheticLog(2, 3);
  for (TimeStep& step : log.steps) step.time = 0.0;
  const std::vector<double> dt = stepDurations(log);
  for (std::size_t k = 1; k < dt.size(); ++k) EXPECT_EQ(dt[k], 1.0);
  log.steps[2].time = 5.0;  // neither increasing nor all equal
  EXPECT_THROW(stepDurations(log), std::invalid_argument);
}

TEST(LogPerturbation, ScaleZeroLeavesTheLogBitIdentical) {
  test::StudyScratch scratch;
  const MeasurementLog log = test::smallSemanticLog(30);
  std::mt19937 rng = perturbationStream(7, 1);
  const MeasurementLog same = addOdometryNoise(log, 0.0, rng);
  EXPECT_EQ(test::logBytes(log, scratch, "a.jsonl"), test::logBytes(same, scratch, "b.jsonl"));
  std::mt19937 rng2 = perturbationStream(7, 1);
  const MeasurementLog noisy = addOdometryNoise(log, 1.0, rng2);
  EXPECT_NE(test::logBytes(log, scratch, "a.jsonl"), test::logBytes(noisy, scratch, "c.jsonl"));
}

TEST(LogPerturbation, SameSeedSameLogOtherSeedOtherLog) {
  test::StudyScratch scratch;
  const MeasurementLog log = test::smallSemanticLog(30);
  LogPerturbation perturbation;
  perturbation.odometryNoiseScale = 2.0;
  perturbation.misclassification = 0.2;
  const std::string a = test::logBytes(perturbLog(log, perturbation, 11), scratch, "a.jsonl");
  const std::string b = test::logBytes(perturbLog(log, perturbation, 11), scratch, "b.jsonl");
  const std::string c = test::logBytes(perturbLog(log, perturbation, 12), scratch, "c.jsonl");
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  perturbation.maxSteps = 10;
  EXPECT_EQ(perturbLog(log, perturbation, 11).steps.size(), 10u);
}

TEST(LogPerturbation, LabelsAreRedrawnAtTheConfusionRate) {
  const MeasurementLog log = syntheticLog(2, 400, 30);  // 400 x 30 landmark detections, 400 clutter
  const double p = 0.3;
  std::mt19937 rng = perturbationStream(5, 2);
  const MeasurementLog redrawn = redrawLabels(log, p, rng);
  EXPECT_EQ(redrawn.header.classifier.kind, ClassifierModelSpec::Kind::Categorical);
  EXPECT_EQ(redrawn.header.classifier.misclassification, p);
  long long n = 0, wrong = 0, clutter = 0;
  std::vector<long long> wrongTo(3, 0), clutterLabels(3, 0);
  for (const TimeStep& step : redrawn.steps) {
    for (const Detection& detection : step.detections) {
      ASSERT_TRUE(detection.label.has_value());
      ASSERT_GE(*detection.label, 0);
      ASSERT_LT(*detection.label, 3);
      if (*detection.truthId == kNotALandmark) {
        ++clutter;
        ++clutterLabels[*detection.label];
        continue;
      }
      const int c = *detection.truthId % 3;
      ++n;
      if (*detection.label != c) {
        ++wrong;
        ++wrongTo[(*detection.label - c + 3) % 3];  // 1 or 2 classes further
      }
    }
  }
  const double se = std::sqrt(p * (1 - p) / n);
  EXPECT_NEAR(static_cast<double>(wrong) / n, p, 4.0 * se);
  // Wrong labels are spread evenly over the other two classes.
  EXPECT_NEAR(static_cast<double>(wrongTo[1]) / wrong, 0.5, 4.0 * std::sqrt(0.25 / wrong));
  // Clutter labels are uniform.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(static_cast<double>(clutterLabels[c]) / clutter, 1.0 / 3, 4.0 * std::sqrt(2.0 / 9 / clutter));
  }
}

TEST(LogPerturbation, RateZeroGivesTrueLabelsAndRatesAreNested) {
  const MeasurementLog log = syntheticLog(2, 50, 10);
  auto redraw = [&](double p) {
    std::mt19937 rng = perturbationStream(9, 2);
    return redrawLabels(log, p, rng);
  };
  const MeasurementLog exact = redraw(0.0), low = redraw(0.1), high = redraw(0.4);
  int wrongLow = 0, wrongHigh = 0;
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    for (std::size_t j = 0; j < log.steps[k].detections.size(); ++j) {
      const int truth = *log.steps[k].detections[j].truthId;
      if (truth == kNotALandmark) {
        EXPECT_EQ(*low.steps[k].detections[j].label, *high.steps[k].detections[j].label);  // p-independent
        continue;
      }
      EXPECT_EQ(*exact.steps[k].detections[j].label, truth % 3);
      const bool isWrongLow = *low.steps[k].detections[j].label != truth % 3;
      const bool isWrongHigh = *high.steps[k].detections[j].label != truth % 3;
      if (isWrongLow) EXPECT_TRUE(isWrongHigh) << "a detection misclassified at 0.1 but not at 0.4";
      wrongLow += isWrongLow;
      wrongHigh += isWrongHigh;
    }
  }
  EXPECT_GT(wrongHigh, wrongLow);
}

TEST(LogPerturbation, ModelFloorOnlyChangesTheHeaderRate) {
  const MeasurementLog log = syntheticLog(2, 20, 5);
  LogPerturbation exact;
  exact.misclassification = 0.0;
  LogPerturbation floored = exact;
  floored.modelMisclassificationFloor = 1e-3;
  const MeasurementLog a = perturbLog(log, exact, 4), b = perturbLog(log, floored, 4);
  EXPECT_EQ(a.header.classifier.misclassification, 0.0);
  EXPECT_EQ(b.header.classifier.misclassification, 1e-3);
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    for (std::size_t j = 0; j < log.steps[k].detections.size(); ++j) {
      EXPECT_EQ(*a.steps[k].detections[j].label, *b.steps[k].detections[j].label);
    }
  }
  floored.misclassification = 0.2;  // above the floor: the exact rate
  EXPECT_EQ(perturbLog(log, floored, 4).header.classifier.misclassification, 0.2);
}

TEST(LogPerturbation, TrueClassFromLandmarkTruthOrIdModClasses) {
  LogHeader header;
  header.classes = 4;
  header.landmarkTruth.push_back({7, 2, Point2(0.0, 0.0)});
  header.landmarkTruth.push_back({8, -1, Point2(0.0, 0.0)});
  EXPECT_EQ(trueLandmarkClass(header, 7), 2);
  EXPECT_EQ(trueLandmarkClass(header, 8), 0);  // unknown class: 8 mod 4
  EXPECT_EQ(trueLandmarkClass(header, 13), 1);
}

TEST(LogPerturbation, BadArgumentsThrow) {
  const MeasurementLog log = syntheticLog(2, 3, 2);
  std::mt19937 rng = perturbationStream(1, 1);
  EXPECT_THROW(addOdometryNoise(log, -1.0, rng), std::invalid_argument);
  EXPECT_THROW(addOdometryNoise(log, std::nan(""), rng), std::invalid_argument);
  EXPECT_THROW(redrawLabels(log, 1.0, rng), std::invalid_argument);
  EXPECT_THROW(redrawLabels(log, -0.1, rng), std::invalid_argument);
  MeasurementLog unknown = log;
  unknown.steps[1].detections[0].truthId.reset();
  EXPECT_THROW(redrawLabels(unknown, 0.1, rng), std::invalid_argument);
  MeasurementLog oneClass = log;
  oneClass.header.classes = 1;
  EXPECT_THROW(redrawLabels(oneClass, 0.1, rng), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
