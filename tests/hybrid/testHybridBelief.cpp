// HybridBelief (paper A, Algorithm 1): against closed forms and against the plain smoother.

#include <gtest/gtest.h>

#include <cmath>

#include "HybridTestLogs.h"
#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/hybrid/HybridBelief.h"
#include "semslam/hybrid/HybridMarginals.h"
#include "semslam/hybrid/HybridRun.h"
#include "semslam/solve/BatchSmoother.h"
#include "support/GaussianDensity.h"

using namespace semslam;
using namespace semslam::test;

namespace {

/// The weight of the component associating detection 0 with object j.
double weightOf(const HybridBelief& belief, int object) {
  for (const HybridComponent& c : belief.components()) {
    if (c.history.back()[0] == belief.problem().objectId(object)) return c.weight;  // histories hold log ids
  }
  return 0.0;
}

}  // namespace

TEST(HybridBelief, AnalyticWeightsEqualTheClosedFormOnALinearGaussianToy) {
  const MeasurementLog log = linearToyLog({Point2(2.0, 0.5), Point2(2.5, -0.3), Point2(1.0, 2.0)}, {Vector2(2.2, 0.1)});
  const HybridProblem problem(log.header, false);
  HybridBelief belief(problem, unpruned(WeightMethod::Analytic));
  belief.update(log.steps[0]);
  const std::vector<double> expected = closedFormWeights(log);
  ASSERT_EQ(belief.components().size(), 3u);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(weightOf(belief, j), expected[j], 1e-9) << "object " << j;
}

TEST(HybridBelief, ImportanceWeightsEqualTheClosedFormOnALinearGaussianToy) {
  // The linearised-posterior proposal is the exact posterior of a linear-Gaussian model: every importance weight
  // is p(z), so even 5 samples give the closed form (up to the toy's tiny pose-rotation nonlinearity: weights
  // vary by ~3e-7).
  const MeasurementLog log = linearToyLog({Point2(2.0, 0.5), Point2(2.5, -0.3), Point2(1.0, 2.0)}, {Vector2(2.2, 0.1)});
  const HybridProblem problem(log.header, false);
  HybridBelief belief(problem, unpruned(WeightMethod::Importance, 5));
  const HybridStepReport report = belief.update(log.steps[0]);
  const std::vector<double> expected = closedFormWeights(log);
  ASSERT_EQ(belief.components().size(), 3u);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(weightOf(belief, j), expected[j], 1e-6) << "object " << j;
  EXPECT_LT(report.weights.maxRelativeStandardError, 1e-5);
  EXPECT_EQ(parseWeightMethod("importance"), WeightMethod::Importance);
  EXPECT_STREQ(weightMethodName(WeightMethod::Importance), "importance");
  EXPECT_THROW(parseWeightMethod("magic"), std::invalid_argument);
}

TEST(HybridBelief, SampledWeightsMatchTheClosedFormWithinTheirMonteCarloError) {
  // A likelihood broad against the prior keeps the Monte Carlo variance moderate.
  const MeasurementLog log = linearToyLog({Point2(2.0, 0.5), Point2(2.5, -0.3), Point2(1.0, 1.5)}, {Vector2(2.2, 0.1)},
                                          0.1, 0.2, 0.6);
  const HybridProblem problem(log.header, false);
  const int samples = 20000;
  HybridOptions options = unpruned(WeightMethod::Sampled, samples);
  options.seed = 42;
  HybridBelief belief(problem, options);
  const HybridStepReport report = belief.update(log.steps[0]);
  const std::vector<double> expected = closedFormWeights(log);
  // Each unnormalised weight has relative standard error ≤ maxRelativeStandardError; a normalised weight w is a
  // ratio, whose relative error is at most about twice that. Allow four standard errors.
  const double relative = report.weights.maxRelativeStandardError;
  ASSERT_GT(relative, 0.0);
  ASSERT_LT(relative, 0.02);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(weightOf(belief, j), expected[j], 4.0 * 2.0 * relative * expected[j] + 1e-4) << "object " << j;
  }
}

TEST(HybridBelief, OneHypothesisWithKnownAssociationEqualsThePlainSmoother) {
  // One object: every detection can only be that object, so each class realization has one component, which
  // must equal a smoother given the same factors (with semantics: the heaviest component's class).
  const MeasurementLog log = simulateAliased2dTrack(smallAliasedScenario(1), 3, 0, 5);
  std::size_t detections = 0;
  for (const TimeStep& step : log.steps) detections += step.detections.size();
  ASSERT_GE(detections, 2u);
  for (bool semantics : {false, true}) {
    const HybridProblem problem(log.header, semantics);
    HybridOptions options;
    options.useSemantics = semantics;
    options.samples = 50;
    HybridBelief belief(problem, options);
    for (const TimeStep& step : log.steps) belief.update(step);
    const HybridComponent& c = belief.components()[belief.heaviest()];
    if (!semantics) {
      EXPECT_EQ(belief.components().size(), 1u);
      EXPECT_DOUBLE_EQ(c.weight, 1.0);
    } else {
      EXPECT_LE(belief.components().size(), 2u);
    }
    const int cls = semantics ? c.classes[0] : 0;

    std::unique_ptr<Smoother> plain = defaultSmootherFactory()();
    FactorGraph graph;
    Values values;
    problem.priors(graph, values);
    plain->update(graph, values);
    for (std::size_t k = 0; k < log.steps.size(); ++k) {
      const Key x = poseKey(k);
      if (k > 0) {
        FactorGraph motion;
        Values initial;
        motion.add(problem.factory().odometryFactor(poseKey(k - 1), x, *log.steps[k].odometry));
        initial.insert(x, problem.factory().predictPose(plain->estimate().value(poseKey(k - 1)), *log.steps[k].odometry));
        plain->update(motion, initial);
      }
      FactorGraph factors;
      for (const Detection& d : log.steps[k].detections) {
        for (const FactorPtr& f : problem.detectionFactors(x, 0, d, cls)) factors.add(f);
      }
      if (!factors.empty()) plain->update(factors);
    }
    for (std::size_t k = 0; k < log.steps.size(); ++k) {
      const SE2& a = c.smoother->estimate<SE2>(poseKey(k));
      const SE2& b = plain->estimate<SE2>(poseKey(k));
      EXPECT_NEAR((a.translation() - b.translation()).norm(), 0.0, 1e-6) << "step " << k;
      EXPECT_NEAR(a.theta(), b.theta(), 1e-6);
    }
    const Matrix covariance = c.smoother->marginalCovariance(poseKey(log.steps.size() - 1));
    const Matrix plainCovariance = plain->marginalCovariance(poseKey(log.steps.size() - 1));
    EXPECT_LE((covariance - plainCovariance).cwiseAbs().maxCoeff(), 1e-6 * (1.0 + plainCovariance.norm()));
  }
}

TEST(HybridBelief, ClassCollapsingGivesTheMarginalsOfFullEnumeration) {
  const MeasurementLog log = simulateAliased2dTrack(smallAliasedScenario(3), 7, 0, 3);
  const HybridProblem problem(log.header, true);
  HybridOptions options;
  options.weights = WeightMethod::Analytic;
  options.pruneRatio = 0.0;
  options.gateRatio = 0.0;
  HybridOptions full = options;
  full.enumerateAllClasses = true;
  HybridBelief collapsed(problem, options), enumerated(problem, full);
  EXPECT_EQ(collapsed.components().size(), 1u);
  EXPECT_EQ(enumerated.components().size(), 8u);
  std::size_t detections = 0;
  for (const TimeStep& step : log.steps) {
    collapsed.update(step);
    enumerated.update(step);
    detections += step.detections.size();
    const HybridMarginals a = hybridMarginals(collapsed), b = hybridMarginals(enumerated);
    EXPECT_LT(collapsed.components().size(), enumerated.components().size());
    ASSERT_EQ(a.association.size(), b.association.size());
    for (std::size_t i = 0; i < a.association.size(); ++i) {
      EXPECT_EQ(a.association[i].associations, b.association[i].associations);
      EXPECT_NEAR(a.association[i].weight, b.association[i].weight, 1e-9);
    }
    ASSERT_EQ(a.classes.rows(), 3);
    EXPECT_LE((a.classes - b.classes).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_NEAR(a.mixtureMean.x(), b.mixtureMean.x(), 1e-7);
    EXPECT_NEAR(evaluateHypotheses(a.components, step.truePose).entropy,
                evaluateHypotheses(b.components, step.truePose).entropy, 1e-9);
  }
  EXPECT_GT(detections, 0u);
}

TEST(HybridBelief, SameSeedSameBeliefBitForBit) {
  const MeasurementLog log = simulateAliased2dTrack(smallAliasedScenario(4), 5, 1, 3);
  HybridOptions options;
  options.samples = 200;
  options.seed = 9;
  const HybridRunOutput a = runHybrid(log, options), b = runHybrid(log, options);
  ASSERT_EQ(a.result.components.size(), b.result.components.size());
  for (std::size_t i = 0; i < a.result.components.size(); ++i) {
    EXPECT_EQ(a.result.components[i].weight, b.result.components[i].weight);
    EXPECT_EQ(a.result.components[i].associations, b.result.components[i].associations);
  }
}

TEST(HybridBelief, GeometricModeEnumeratesNoClasses) {
  const MeasurementLog log = simulateAliased2dTrack(smallAliasedScenario(3), 7, 0, 2);
  HybridOptions options;
  options.useSemantics = false;
  options.samples = 100;
  const HybridRunOutput out = runHybrid(log, options);
  for (const HypothesisComponent& c : out.result.components) EXPECT_TRUE(c.classes.empty());
  EXPECT_EQ(out.finalMarginals.classes.size(), 0);
  EXPECT_EQ(out.result.method, "hybrid-geometric");
}

TEST(HybridBelief, OneDetectionAtATimeAgreesWithWholeAssociationsWhenNothingIsPruned) {
  const MeasurementLog log = simulateAliased2dTrack(smallAliasedScenario(3), 7, 0, 3);
  HybridOptions whole;
  whole.weights = WeightMethod::Analytic;
  whole.pruneRatio = 0.0;
  whole.gateRatio = 0.0;
  whole.useSemantics = false;
  HybridOptions sequential = whole;
  sequential.branching = Branching::OneDetectionAtATime;
  sequential.jointCompatibility = 1.0 - 1e-12;  // keeps practically everything
  const HybridRunOutput a = runHybrid(log, whole), b = runHybrid(log, sequential);
  const auto& ma = a.finalMarginals.association;
  const auto& mb = b.finalMarginals.association;
  ASSERT_FALSE(ma.empty());
  EXPECT_EQ(ma.front().associations, mb.front().associations);
  EXPECT_NEAR(ma.front().weight, mb.front().weight, 1e-6);
}

// Bounded memory (HybridOptions: maxCandidates, maxComponents): a bound that binds changes how the step branches
// and is reported, never a crash or an allocation sized by the unbounded count.
TEST(HybridBelief, PastTheCandidateBoundAWholeStepBranchesOneDetectionAtATimeAndSaysSo) {
  // Two detections among six objects with classes: up to 6 · 5 · 2² = 120 candidates per parent.
  const MeasurementLog log = linearToyLog({Point2(1, 0), Point2(3, 0), Point2(5, 0), Point2(7, 0), Point2(9, 0),
                                           Point2(11, 0)},
                                          {Vector2(1, 0), Vector2(3, 0)});
  HybridOptions bounded;
  bounded.weights = WeightMethod::Analytic;
  bounded.useSemantics = false;
  bounded.maxCandidates = 29;  // 6 · 5 = 30 whole associations
  const HybridRunOutput out = runHybrid(log, bounded);
  const PropWeightsReport& report = out.reports.front().weights;
  EXPECT_TRUE(report.branchedOneAtATime);
  EXPECT_EQ(report.wholeAssociationBound, 30.0);
  EXPECT_LE(report.candidates, 29u);
  const std::string note = describeBoundsThatBound(out.reports, bounded);
  EXPECT_NE(note.find("branched one detection at a time"), std::string::npos) << note;
  EXPECT_NE(note.find("--max-candidates 29"), std::string::npos) << note;

  HybridOptions loose = bounded;
  loose.maxCandidates = 30;
  const HybridRunOutput whole = runHybrid(log, loose);
  EXPECT_FALSE(whole.reports.front().weights.branchedOneAtATime);
  EXPECT_EQ(whole.reports.front().weights.candidates, 30u);
  EXPECT_EQ(describeBoundsThatBound(whole.reports, loose), "");
}

TEST(HybridBelief, OneDetectionAtATimeKeepsAtMostTheCandidateBoundOfPartialAssociations) {
  const MeasurementLog log = linearToyLog({Point2(1, 0), Point2(1.1, 0), Point2(1.2, 0), Point2(1.3, 0)},
                                          {Vector2(1, 0), Vector2(1.2, 0)}, 0.3, 0.5, 0.5);
  HybridOptions options;
  options.weights = WeightMethod::Analytic;
  options.useSemantics = false;
  options.branching = Branching::OneDetectionAtATime;
  options.jointCompatibility = 1.0 - 1e-12;
  options.gateRatio = 0.0;
  options.maxCandidates = 3;
  const HybridRunOutput out = runHybrid(log, options);
  const HybridStepReport& report = out.reports.front();
  EXPECT_LE(report.weights.candidates, 3u);
  EXPECT_GT(report.weights.truncatedPartials, 0u);
  EXPECT_NE(describeBoundsThatBound(out.reports, options).find("heaviest partial associations"), std::string::npos);
}

TEST(HybridBelief, TheComponentCapIsReportedWhenItBinds) {
  const MeasurementLog log = linearToyLog({Point2(1, 0), Point2(1.1, 0), Point2(1.2, 0)}, {Vector2(1.1, 0)});
  HybridOptions options;
  options.weights = WeightMethod::Analytic;
  options.useSemantics = false;
  options.pruneRatio = 0.0;
  options.maxComponents = 2;
  const HybridRunOutput out = runHybrid(log, options);
  EXPECT_EQ(out.result.components.size(), 2u);
  EXPECT_EQ(out.reports.front().cappedComponents, 1u);
  EXPECT_NE(describeBoundsThatBound(out.reports, options).find("--max-components 2"), std::string::npos);
}

TEST(HybridBelief, TheMemoryBoundKeepsFewerComponentsAndSaysSo) {
  // Three equally plausible objects: three children. A budget sized from the smoother's own count holds two.
  const MeasurementLog log = linearToyLog({Point2(1, 0), Point2(1.1, 0), Point2(1.2, 0)}, {Vector2(1.1, 0)});
  HybridOptions options;
  options.weights = WeightMethod::Analytic;
  options.useSemantics = false;
  options.pruneRatio = 0.0;
  const HybridRunOutput unbounded = runHybrid(log, options);
  ASSERT_EQ(unbounded.result.components.size(), 3u);
  const double componentBytes = unbounded.reports.front().componentBytes;
  ASSERT_GT(componentBytes, 0.0);
  EXPECT_EQ(unbounded.reports.front().memoryCappedComponents, 0u);

  HybridOptions bounded = options;
  bounded.maxMemoryMiB = 3.0 * 2.5 * componentBytes / (1024.0 * 1024.0);  // room for 2.5 components, 3 copies each
  const HybridRunOutput out = runHybrid(log, bounded);
  EXPECT_EQ(out.result.components.size(), 2u);
  EXPECT_EQ(out.reports.front().cappedComponents, 1u);
  EXPECT_EQ(out.reports.front().memoryCappedComponents, 1u);
  const std::string note = describeBoundsThatBound(out.reports, bounded);
  EXPECT_NE(note.find("the memory bound (--max-memory"), std::string::npos) << note;
  EXPECT_EQ(note.find("the component cap"), std::string::npos) << note;  // the count cap did not bind

  // Where the count cap binds first, the memory bound is not blamed.
  HybridOptions counted = bounded;
  counted.maxComponents = 1;
  const HybridRunOutput countedOut = runHybrid(log, counted);
  EXPECT_EQ(countedOut.reports.front().cappedComponents, 2u);
  EXPECT_EQ(countedOut.reports.front().memoryCappedComponents, 0u);

  // A budget that holds not one component: a message naming the bound, not a crash.
  HybridOptions tiny = options;
  tiny.maxMemoryMiB = 0.5 * componentBytes / (1024.0 * 1024.0);
  try {
    runHybrid(log, tiny);
    FAIL() << "expected the memory bound to refuse the step";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("raise --max-memory"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("step 0"), std::string::npos) << error.what();
  }
}

TEST(HybridBelief, RejectsLogsWithoutAMapOrInitialPrior) {
  MeasurementLog log = linearToyLog({Point2(1, 0)}, {Vector2(1, 0)});
  log.header.landmarkPriors.clear();
  EXPECT_ANY_THROW(HybridProblem(log.header, false));
  log = linearToyLog({Point2(1, 0)}, {Vector2(1, 0)});
  log.header.initialPose.reset();
  EXPECT_ANY_THROW(HybridProblem(log.header, false));
}
