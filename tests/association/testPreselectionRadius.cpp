// PreselectionRadius (docs/association-front-end.md, §7): every landmark whose linearised innovation passes the gate
// lies inside the pre-selection ball, on seeded random poses, joint covariances (correlated, with heading
// uncertainty), sensor mountings and detections, for each sensor kind in 2D and 3D; the ball is not vacuous (some
// passing landmarks come close to its edge); the semantic allowance bounds the joint gate's semantic term.

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <random>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/ClassBelief.h"
#include "semslam/association/MarginalLikelihood.h"
#include "semslam/association/PreselectionRadius.h"
#include "support/RandomGeometry.h"

using namespace semslam;

namespace {

struct Case {
  const char* name;
  int dimension;
  SensorKind kind;
  bool landmarksHavePose = false;
};

LogHeader headerFor(const Case& c, test::RandomSpace& random) {
  LogHeader header;
  header.dimension = c.dimension;
  header.landmarksHavePose = c.landmarksHavePose;
  header.sensor.kind = c.kind;
  const bool mounted = c.kind == SensorKind::RangeBearing || c.kind == SensorKind::RangeBearingElevation;
  if (c.dimension == 2) {
    const double x = random.uniform(-0.5, 0.5), y = random.uniform(-0.5, 0.5);
    header.sensor.bodyToSensor = mounted ? SE2(x, y, random.uniform(-1, 1)) : SE2();
  } else {
    header.sensor.bodyToSensor =
        mounted ? SE3(random.rotation(), Point3(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5), 0.3)) : SE3();
  }
  return header;
}

/// A random correlated covariance over [pose; landmark] with chosen standard-deviation scales per tangent entry.
Matrix randomJointCovariance(test::RandomSpace& random, const Vector& scales) {
  const int n = static_cast<int>(scales.size());
  Matrix A(n, n);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) A(i, j) = gaussian(random.rng);
  }
  Matrix correlated = A * A.transpose() / n + 0.05 * Matrix::Identity(n, n);
  const Vector d = correlated.diagonal().cwiseSqrt().cwiseInverse();
  correlated = d.asDiagonal() * correlated * d.asDiagonal();  // a correlation matrix
  return scales.asDiagonal() * correlated * scales.asDiagonal();
}

Detection randomDetection(const Case& c, test::RandomSpace& random) {
  Detection detection;
  const double range = random.uniform(1.0, 20.0), bearing = random.uniform(-3.1, 3.1);
  const double rangeSigma = random.uniform(0.01, 0.3), angleSigma = random.uniform(0.002, 0.05);
  if (c.kind == SensorKind::RangeBearing) {
    detection.geometry = Vector2(range, bearing);
    detection.covariance = Vector2(rangeSigma * rangeSigma, angleSigma * angleSigma).asDiagonal();
  } else if (c.kind == SensorKind::RangeBearingElevation) {
    detection.geometry = Vector3(range, bearing, random.uniform(-0.7, 0.7));
    const double angleVariance = angleSigma * angleSigma;
    detection.covariance = Vector3(rangeSigma * rangeSigma, angleVariance, 0.7 * angleVariance).asDiagonal();
  } else {
    Vector p = Vector::Zero(c.dimension);
    p(0) = range * std::cos(bearing);
    p(1) = range * std::sin(bearing);
    if (c.dimension == 3) p(2) = random.uniform(-3.0, 3.0);
    detection.geometry = p;
    Matrix B(c.dimension, c.dimension);
    for (int i = 0; i < B.size(); ++i) B.data()[i] = random.uniform(-1.0, 1.0) * rangeSigma;
    detection.covariance = B * B.transpose() + 1e-4 * Matrix::Identity(c.dimension, c.dimension);
  }
  return detection;
}

Value landmarkAt(const Case& c, const Vector& position, test::RandomSpace& random) {
  if (c.dimension == 2) {
    const Point2 p = position;
    if (c.landmarksHavePose) return SE2(SO2(random.uniform(-3, 3)), p);
    return p;
  }
  const Point3 p = position;
  if (c.landmarksHavePose) return SE3(random.rotation(), p);
  return p;
}

struct Outcome {
  int passing = 0;
  int unbounded = 0;
  double largestPassingRatio = 0.0;  // max over passing landmarks of D / (their ball radius)
};

Outcome checkCase(const Case& c, unsigned seed) {
  test::RandomSpace random(seed);
  const AssociationGate gate;
  Outcome outcome;
  for (int trial = 0; trial < 300; ++trial) {
    const LogHeader header = headerFor(c, random);
    const MeasurementFactory factory(header);
    const int p = factory.poseTangentDimension(), l = factory.landmarkTangentDimension(), d = c.dimension;
    const Value pose = d == 2 ? Value(SE2(random.uniform(-50, 50), random.uniform(-50, 50), random.uniform(-3, 3)))
                              : Value(SE3(random.rotation(), Point3(random.uniform(-50, 50), random.uniform(-50, 50),
                                                                     random.uniform(-5, 5))));
    Vector scales(p + l);
    const double translation = random.uniform(0.01, 1.0), rotation = random.uniform(0.0005, 0.06);
    const double landmarkScale = random.uniform(0.01, 1.0);
    for (int i = 0; i < p + l; ++i) {
      const bool poseEntry = i < p, poseTranslation = i < d, landmarkTranslation = i >= p && i < p + d;
      scales(i) = poseEntry ? (poseTranslation ? translation : rotation) * random.uniform(0.3, 1.0)
                            : (landmarkTranslation ? landmarkScale * random.uniform(0.3, 1.0) : 0.1);
    }
    const Matrix joint = randomJointCovariance(random, scales);
    const Detection detection = randomDetection(c, random);
    const int m = gateDegreesOfFreedom(header.sensor, d);
    const double threshold = gate.threshold(m) + (trial % 3 == 0 ? random.uniform(0.0, 8.0) : 0.0);
    const auto ball = preselectionBall(factory, header.sensor, pose, joint.topLeftCorner(p, p), detection, threshold);
    if (!ball) {
      ++outcome.unbounded;
      continue;
    }
    const double spread = positionSpread(joint.bottomRightCorner(l, l), d);
    const double radius = ball->base + ball->slope * spread;
    const JointMarginal marginal({poseKey(0), landmarkKey(0)}, {p, l}, joint);
    const std::vector<FactorPtr> factor = {factory.detectionFactor(poseKey(0), landmarkKey(0), detection)};
    for (int s = 0; s < 40; ++s) {
      Vector direction = Vector::Zero(d);
      for (int i = 0; i < d; ++i) direction(i) = random.gaussian3()(0);
      const double distance = radius * std::pow(random.uniform(0.0, 1.0), 3.0) * 1.2;  // most near the centre
      const Vector position = ball->center + direction.normalized() * distance;
      Values values;
      values.insert(poseKey(0), pose);
      values.insert(landmarkKey(0), landmarkAt(c, position, random));
      double chi2 = 0.0;
      try {
        chi2 = linearizedLikelihood(factor, values, marginal).innovationChi2;
      } catch (const std::domain_error&) {
        continue;  // a landmark on the sensor (or its z axis): no bearing
      }
      if (chi2 > threshold) continue;
      ++outcome.passing;
      outcome.largestPassingRatio = std::max(outcome.largestPassingRatio, distance / radius);
      EXPECT_LE(distance, radius) << c.name << " trial " << trial << ": a landmark passes the gate (chi2 " << chi2
                                  << " <= " << threshold << ") outside the ball";
    }
  }
  return outcome;
}

}  // namespace

TEST(PreselectionRadius, EveryLandmarkThatPassesTheGateIsInsideTheBall) {
  const Case cases[] = {
      {"range-bearing 2D", 2, SensorKind::RangeBearing},
      {"range-bearing 2D, posed landmarks", 2, SensorKind::RangeBearing, true},
      {"range-bearing-elevation 3D", 3, SensorKind::RangeBearingElevation},
      {"relative position 2D", 2, SensorKind::RelativePosition},
      {"relative position 3D", 3, SensorKind::RelativePosition},
  };
  unsigned seed = 5;
  for (const Case& c : cases) {
    const Outcome outcome = checkCase(c, seed++);
    EXPECT_GT(outcome.passing, 1000) << c.name;
    EXPECT_LT(outcome.unbounded, 150) << c.name;
    // Not vacuous: passing landmarks reach well into the ball (measured 0.25 in 3D to 0.8 for relative positions;
    // the slack is the triangle inequalities' and λmax ≤ trace's).
    EXPECT_GT(outcome.largestPassingRatio, 0.2) << c.name;
    RecordProperty(std::string(c.name) + " largest D/radius", std::to_string(outcome.largestPassingRatio));
  }
}

TEST(PreselectionRadius, RelativePoseSensorsAndHugeHeadingUncertaintyHaveNoBall) {
  LogHeader header;
  header.sensor.kind = SensorKind::RelativePose;
  header.landmarksHavePose = true;
  const MeasurementFactory relativePose(header);
  Detection detection;
  detection.geometry = Vector3(3.0, 1.0, 0.2);
  detection.covariance = Matrix::Identity(3, 3) * 0.01;
  EXPECT_FALSE(preselectionBall(relativePose, header.sensor, SE2(), Matrix::Identity(3, 3) * 0.01, detection, 27.6));

  header.sensor.kind = SensorKind::RangeBearing;
  header.landmarksHavePose = false;
  const MeasurementFactory rangeBearing(header);
  detection.geometry = Vector2(3.0, 1.0);
  detection.covariance = Matrix::Identity(2, 2) * 1e-4;
  Matrix pose = Matrix::Identity(3, 3) * 0.01;
  EXPECT_TRUE(preselectionBall(rangeBearing, header.sensor, SE2(), pose, detection, 27.6));
  pose(2, 2) = 0.2 * 0.2;  // √2 · √27.6 · 0.2 > 1: the linearised gate bounds no distance
  EXPECT_FALSE(preselectionBall(rangeBearing, header.sensor, SE2(), pose, detection, 27.6));
}

TEST(PreselectionRadius, SemanticAllowanceBoundsTheJointGatesSemanticTerm) {
  // −2 ln(P(s | j) / P₀(s)) ≥ −allowance for every class belief P(c | j).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const int classes = 1 + trial % 5;
    Vector likelihoods(classes), belief(classes);
    for (int c = 0; c < classes; ++c) {
      likelihoods(c) = u(rng) < 0.1 ? 0.0 : u(rng);
      belief(c) = std::pow(u(rng), 4.0);
    }
    if (!(likelihoods.sum() > 0.0) || !(belief.sum() > 0.0)) continue;
    belief /= belief.sum();
    const double predictive = belief.dot(likelihoods), labelPrior = likelihoods.mean();
    if (!(predictive > 0.0)) continue;
    EXPECT_GE(-2.0 * std::log(predictive / labelPrior), -semanticGateAllowance(likelihoods) - 1e-12);
  }
  EXPECT_EQ(semanticGateAllowance(Vector::Ones(4)), 0.0);                        // no semantics
  EXPECT_NEAR(semanticGateAllowance(Vector3(0.8, 0.1, 0.1)), 2.0 * std::log(0.8 / (1.0 / 3.0)), 1e-12);
  EXPECT_EQ(semanticGateAllowance(Vector2(0.0, 0.0)), 0.0);                      // every landmark rules it out
}
