// The hybrid belief on 3D logs (SE3 poses, range-bearing-elevation or relative-position detections, the viewpoint
// classifier about the object's vertical axis, VisibilityModel3). On a level 3D lift of a 2D log (z, roll and
// pitch held by tight priors: sim/Aliased3dLift.h) it is the 2D belief: the same components, weights, histories
// and poses with analytic weights, and sampled weights within their Monte Carlo error of the closed form. On a
// lift with object heights it runs, and the classifier lowers the association entropy over seeded tracks, as in 2D.

#include <gtest/gtest.h>

#include <cmath>

#include "HybridTestLogs.h"
#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/hybrid/HybridBelief.h"
#include "semslam/hybrid/HybridRun.h"
#include "semslam/sim/Aliased3dLift.h"

using namespace semslam;
using namespace semslam::test;

namespace {

struct StepView {
  std::vector<double> weights;
  std::vector<std::vector<std::vector<int>>> histories;
  std::vector<Vector3> poses;  // x, y, heading
  std::vector<Matrix3> covariances;  // of (x, y, heading)
};

/// A level lift held far tighter than the default (σ 1e-6 instead of 1e-4): normalised weights within 1e-6 of the
/// 2D ones (sim/Aliased3dLift.h). In memory only: a log file refuses a prior this badly conditioned.
Aliased3dLift nearlyExactLevel() {
  Aliased3dLift lift;
  lift.levelSigma = 1e-6;
  return lift;
}

std::vector<StepView> runAndRecord(const MeasurementLog& log, const HybridOptions& options) {
  std::vector<StepView> steps;
  runHybrid(log, options, {}, [&](const HybridStepRecord& record) {
    StepView view;
    for (const HypothesisComponent& c : record.marginals.components) {
      view.weights.push_back(c.weight);
      view.histories.push_back(c.associations.steps());
      if (const SE2* planar = std::get_if<SE2>(&c.pose)) {
        view.poses.emplace_back(planar->x(), planar->y(), planar->theta());
        view.covariances.push_back(c.covariance);
      } else {
        const SE3& x = std::get<SE3>(c.pose);
        const Matrix3 R = x.rotation().matrix();
        view.poses.emplace_back(x.translation().x(), x.translation().y(), std::atan2(R(1, 0), R(0, 0)));
        const int level[3] = {0, 1, 5};  // x, y, yaw in the SE3 tangent
        Matrix3 block;
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) block(i, j) = c.covariance(level[i], level[j]);
        }
        view.covariances.push_back(block);
      }
    }
    steps.push_back(std::move(view));
  });
  return steps;
}

TEST(Hybrid3d, ALevelLiftGivesThe2dBeliefWithAnalyticWeights) {
  std::size_t most = 0;
  for (int track : {0, 1, 4}) {
    const MeasurementLog planar = simulateAliased2dTrack(defaultAliased2dScenario(), /*seed=*/2, track, /*steps=*/6);
    const MeasurementLog spatial = liftAliasedLogTo3d(planar, nearlyExactLevel());
    for (bool semantics : {false, true}) {
      HybridOptions options;
      options.useSemantics = semantics;
      options.weights = WeightMethod::Analytic;
      const std::vector<StepView> a = runAndRecord(planar, options), b = runAndRecord(spatial, options);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) {
        ASSERT_EQ(a[k].weights.size(), b[k].weights.size()) << "track " << track << ", step " << k;
        most = std::max(most, a[k].weights.size());
        for (std::size_t i = 0; i < a[k].weights.size(); ++i) {
          EXPECT_NEAR(a[k].weights[i], b[k].weights[i], 1e-6)
              << "track " << track << ", step " << k << (semantics ? ", classifier" : ", geometric");
          EXPECT_EQ(a[k].histories[i], b[k].histories[i]);
          EXPECT_LE((a[k].poses[i] - b[k].poses[i]).cwiseAbs().maxCoeff(), 1e-6) << "step " << k;
          EXPECT_LE((a[k].covariances[i] - b[k].covariances[i]).cwiseAbs().maxCoeff(),
                    1e-6 * (1.0 + a[k].covariances[i].cwiseAbs().maxCoeff()))
              << "step " << k;
        }
      }
    }
  }
  EXPECT_GT(most, 1u) << "the tracks must keep several hypotheses to test anything";
}

TEST(Hybrid3d, SampledWeightsOfALevelLiftMatchThe2dClosedFormWithinTheirMonteCarloError) {
  const MeasurementLog planar = linearToyLog({Point2(2.0, 0.5), Point2(2.5, -0.3), Point2(1.0, 1.5)},
                                             {Vector2(2.2, 0.1)}, 0.1, 0.2, 0.6);
  const MeasurementLog spatial = liftAliasedLogTo3d(planar, nearlyExactLevel());
  const HybridProblem problem(spatial.header, false);
  HybridOptions options = unpruned(WeightMethod::Sampled, 20000);
  options.seed = 42;
  HybridBelief belief(problem, options);
  const HybridStepReport report = belief.update(spatial.steps[0]);
  const std::vector<double> expected = closedFormWeights(planar);
  const double relative = report.weights.maxRelativeStandardError;
  ASSERT_GT(relative, 0.0);
  ASSERT_LT(relative, 0.03);
  ASSERT_EQ(belief.components().size(), 3u);
  for (const HybridComponent& c : belief.components()) {
    const int object = c.history.back()[0] - problem.objectId(0);  // the toy's ids are consecutive
    ASSERT_GE(object, 0);
    ASSERT_LT(object, 3);
    // A normalised weight is a ratio of two estimates: about twice their relative error; four standard errors.
    EXPECT_NEAR(c.weight, expected[object], 4.0 * 2.0 * relative * expected[object] + 1e-4) << "object " << object;
  }
}

TEST(Hybrid3d, WithObjectHeightsTheClassifierLowersTheAssociationEntropy) {
  // Cars on a parking deck at different heights: the classifier's viewpoint model still tells the bays apart.
  double entropyClassifier = 0.0, entropyGeometric = 0.0;
  int tracks = 0;
  for (int track = 0; track < 12; ++track) {
    const MeasurementLog planar = simulateAliased2dTrack(defaultAliased2dScenario(), /*seed=*/3, track, /*steps=*/8);
    Aliased3dLift lift;
    for (std::size_t j = 0; j < planar.header.landmarkTruth.size(); ++j) lift.objectHeights.push_back(0.4 * (j % 3));
    const MeasurementLog spatial = liftAliasedLogTo3d(planar, lift, /*seed=*/3, static_cast<std::uint32_t>(track));
    ASSERT_EQ(spatial.header.dimension, 3);
    HybridOptions options;
    options.weights = WeightMethod::Analytic;
    const HybridRunOutput classifier = runHybrid(spatial, options);
    options.useSemantics = false;
    const HybridRunOutput geometric = runHybrid(spatial, options);
    ASSERT_EQ(classifier.result.poses.size(), spatial.steps.size());
    ASSERT_TRUE(std::holds_alternative<SE3>(classifier.result.poses.back()));
    ASSERT_TRUE(std::holds_alternative<SE3>(classifier.result.landmarks.front().state));
    entropyClassifier += evaluateHypotheses(classifier.finalMarginals.components, std::nullopt).entropy;
    entropyGeometric += evaluateHypotheses(geometric.finalMarginals.components, std::nullopt).entropy;
    ++tracks;
  }
  EXPECT_LT(entropyClassifier / tracks, entropyGeometric / tracks);
}

TEST(Hybrid3d, TheLiftRefusesWhatItCannotLift) {
  MeasurementLog planar = simulateAliased2dTrack(defaultAliased2dScenario(), 2, 0, 2);
  Aliased3dLift wrongCount;
  wrongCount.objectHeights = {1.0};
  EXPECT_THROW(liftAliasedLogTo3d(planar, wrongCount), std::invalid_argument);
  Aliased3dLift zeroSigma;
  zeroSigma.levelSigma = 0.0;
  EXPECT_THROW(liftAliasedLogTo3d(planar, zeroSigma), std::invalid_argument);
  const MeasurementLog spatial = liftAliasedLogTo3d(planar, Aliased3dLift{});
  EXPECT_THROW(liftAliasedLogTo3d(spatial, Aliased3dLift{}), std::invalid_argument);  // already 3D
}

}  // namespace
