// The aliasing property of the default aliased2d layout (docs/simulators.md, "Why the default is aliased"):
//   - the bays are congruent: bay b + 1 is bay b translated by the bay shift D (no rotation, so the heading
//     prior of paper A, std 0.2 rad, cannot tell the hypotheses apart either);
//   - seen from a pose x and from x + D, the visible objects correspond one to one, so the same range-bearing
//     measurements have exactly the same geometric likelihood, and the same visibility-model probability,
//     under the true association at x and the shifted association at x + D;
//   - but corresponding cars are parked facing different ways, so the viewpoint-dependent classifier's
//     predicted scores differ: the expected log-likelihood ratio ½ m² (m: the Mahalanobis distance between the
//     two predicted score means) favours the truth.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "semslam/graph/NoiseModel.h"
#include "semslam/models/AnalyticViewpointClassifier.h"
#include "semslam/models/Angle.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/Sampling.h"
#include "semslam/models/Viewpoint.h"
#include "semslam/models/VisibilityModel.h"
#include "semslam/sim/Aliased2dSimulator.h"

namespace semslam {
namespace {

constexpr double kPi = std::numbers::pi;

struct Layout {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  Point2 shift = defaultAliased2dBayShift();
  std::vector<Point2> positions;
  std::vector<SE2> poses;
  Layout() {
    for (const Aliased2dObject& object : scenario.objects) {
      positions.push_back(object.pose.translation());
      poses.push_back(object.pose);
    }
  }
  VisibilityModel2 visibility() const {
    return VisibilityModel2(scenario.sensor.fieldOfView, scenario.sensor.maxRange, scenario.sensor.bodyToSensor);
  }
  /// The object at position(i) + m·D, or -1.
  int shifted(int i, int m) const {
    for (std::size_t j = 0; j < positions.size(); ++j) {
      if ((positions[j] - positions[i] - m * shift).norm() < 1e-12) return static_cast<int>(j);
    }
    return -1;
  }
};

SE2 translated(const SE2& pose, const Point2& t) { return SE2(pose.x() + t.x(), pose.y() + t.y(), pose.theta()); }

/// log N(z; h(x, l), Σ) summed over the detections, with detection i associated to object beta[i].
double geometricLogLikelihood(const std::vector<Vector2>& z, const SE2& x, const std::vector<int>& beta,
                              const Layout& layout) {
  const RangeBearingSensor2 sensor(layout.scenario.sensor.bodyToSensor);
  const SharedNoiseModel noise = NoiseModel::fromCovariance(layout.scenario.sensor.covariance);
  double sum = 0.0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    const Vector2 r = RangeBearingSensor2::difference(z[i], sensor.predict(x, layout.positions[beta[i]]));
    sum += -0.5 * noise->whiten(r).squaredNorm() - noise->logNormalizer();
  }
  return sum;
}

/// Σ over the visible objects of the Mahalanobis² distance between the classifier's predicted score means for
/// object i seen from x and for object alias(i) seen from xAlias (their true class, 0).
double semanticSeparation(const SE2& x, const SE2& xAlias, const std::vector<int>& visible, int m,
                          const Layout& layout) {
  const AnalyticViewpointClassifier classifier(layout.scenario.alpha, layout.scenario.sharpness);
  const SharedNoiseModel noise = classifier.noiseModel(0, 0.0);
  double sum = 0.0;
  for (int i : visible) {
    const int j = layout.shifted(i, m);
    const Vector d = classifier.mean(0, viewpointAngle(x, layout.poses[i])) -
                     classifier.mean(0, viewpointAngle(xAlias, layout.poses[j]));
    sum += noise->whiten(d).squaredNorm();
  }
  return sum;
}

TEST(Aliasing, TheBaysAreTranslatedCopiesWithDifferentlyParkedCars) {
  const Layout layout;
  ASSERT_EQ(layout.positions.size(), 6u);
  for (int bay = 0; bay < 2; ++bay) {
    int differing = 0;
    for (int car = 0; car < 2; ++car) {
      const int i = 2 * bay + car;
      EXPECT_EQ(layout.shifted(i, 1), i + 2) << "object " << i;
      if (std::abs(wrapAngle(layout.poses[i + 2].theta() - layout.poses[i].theta())) > 1.0) ++differing;
    }
    EXPECT_GE(differing, 1) << "bays " << bay << " and " << bay + 1 << " are parked alike";
  }
  int differing = 0;  // bays 0 and 2
  for (int car = 0; car < 2; ++car) {
    if (std::abs(wrapAngle(layout.poses[car + 4].theta() - layout.poses[car].theta())) > 1.0) ++differing;
  }
  EXPECT_GE(differing, 1);
}

TEST(Aliasing, GeometryAloneCannotTellTheFirstViewFromItsShiftedCopies) {
  const Layout layout;
  const VisibilityModel2 visibility = layout.visibility();
  // The first pose of a track that sets out straight: one step ahead of the start.
  const SE2 x = layout.scenario.start.compose(SE2::Exp(Vector3(layout.scenario.motion.stepLength, 0.0, 0.0)));
  const std::vector<int> visible = visibility.visibleObjects(x, layout.positions);
  ASSERT_EQ(visible, (std::vector<int>{0, 1}));  // both cars of bay 0

  // Measurements drawn at the truth.
  std::mt19937 rng(2024);
  const RangeBearingSensor2 sensor(layout.scenario.sensor.bodyToSensor);
  std::vector<Vector2> z;
  for (int i : visible) {
    z.push_back(Vector2(
        sampleGaussian(Vector(sensor.predict(x, layout.positions[i])), layout.scenario.sensor.covariance, rng)));
  }
  const double truth = geometricLogLikelihood(z, x, visible, layout);
  for (int m = 1; m <= 2; ++m) {
    const SE2 xAlias = translated(x, m * layout.shift);
    std::vector<int> beta;
    for (int i : visible) beta.push_back(layout.shifted(i, m));
    // The aliased pose sees exactly the shifted objects, and nothing else.
    EXPECT_EQ(visibility.visibleObjects(xAlias, layout.positions), beta) << "shift " << m;
    EXPECT_TRUE(visibility.associationFeasible(xAlias, layout.positions, beta));
    EXPECT_EQ(visibility.associationProbability(xAlias, layout.positions, beta),
              visibility.associationProbability(x, layout.positions, visible));
    // Identical geometric likelihood.
    EXPECT_NEAR(geometricLogLikelihood(z, xAlias, beta, layout), truth, 1e-9) << "shift " << m;
    // The heading is the same, so paper A's initial prior (Σ_p = diag(100, 100, 0.04)) separates the two
    // positions only by ½ |m D|² / 100.
    EXPECT_LE(0.5 * (m * layout.shift).squaredNorm() / layout.scenario.priors.initialPoseCovariance(0, 0), 0.75);
    // The classifier separates them: expected log-likelihood ratio ½ m² ≥ 2.
    const double separation = semanticSeparation(x, xAlias, visible, m, layout);
    EXPECT_GE(separation, 4.0) << "shift " << m;
  }
}

TEST(Aliasing, SampledTracksMeetAliasedViewsThatTheClassifierSeparates) {
  // Over the default run (50 tracks of 10 steps, Fig. 3b), count the steps whose view is geometrically
  // aliased with a view shifted by whole bays, and how strongly the classifier separates them.
  const Layout layout;
  const VisibilityModel2 visibility = layout.visibility();
  int steps = 0, aliased = 0, separated = 0;
  std::map<int, int> byShift;
  for (int track = 0; track < 50; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(layout.scenario, 1, track, 10, 50);
    for (std::size_t k = 1; k < log.steps.size(); ++k) {
      const SE2 x = std::get<SE2>(*log.steps[k].truePose);
      const std::vector<int> visible = visibility.visibleObjects(x, layout.positions);
      if (visible.empty()) continue;
      ++steps;
      for (int m : {-2, -1, 1, 2}) {
        std::vector<int> beta;
        for (int i : visible) beta.push_back(layout.shifted(i, m));
        if (std::find(beta.begin(), beta.end(), -1) != beta.end()) continue;
        const SE2 xAlias = translated(x, m * layout.shift);
        if (visibility.visibleObjects(xAlias, layout.positions) != beta) continue;
        ++aliased;
        ++byShift[m];
        if (semanticSeparation(x, xAlias, visible, m, layout) >= 1.0) ++separated;
      }
    }
  }
  ASSERT_GT(steps, 300);
  // Most views with an object in sight have at least one exact geometric alias ...
  EXPECT_GT(aliased, steps / 2) << aliased << " aliases in " << steps << " steps";
  EXPECT_GT(byShift[1], 0);
  EXPECT_GT(byShift[2], 0);
  // ... and the classifier separates most of those (the rest see only cars parked alike in both bays).
  EXPECT_GT(separated, aliased / 2) << separated << " of " << aliased;
}

}  // namespace
}  // namespace semslam
