// SemanticSlam::fork(): an independent copy of a run, which continues exactly as a single run would.

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <vector>

#include "semslam/sim/DemoScenario.h"
#include "semslam/slam/SemanticSlam.h"

namespace semslam {
namespace {

/// What a finished run decided and estimated: each detection's association and every variable's value.
struct Outcome {
  std::vector<std::optional<int>> associations;
  Values estimate;
  int landmarks = 0;
};

Outcome outcomeOf(SemanticSlam& slam) {
  slam.finish();
  Outcome outcome;
  for (const DetectionRecord& record : slam.detections()) outcome.associations.push_back(slam.chosenAssociation(record).first);
  outcome.estimate = slam.smoother().estimate();
  outcome.landmarks = slam.landmarks();
  return outcome;
}

/// Bit-for-bit equality of two estimates: the same keys, and each value the same type with equal stored coordinates.
void expectSameEstimate(const Values& a, const Values& b) {
  ASSERT_EQ(a.keys(), b.keys());
  for (Key key : a.keys()) {
    const Value& x = a.value(key);
    const Value& y = b.value(key);
    ASSERT_EQ(x.index(), y.index()) << "key " << key;
    if (const auto* p = std::get_if<SE2>(&x)) {
      const SE2& q = std::get<SE2>(y);
      EXPECT_EQ(p->x(), q.x()) << "key " << key;
      EXPECT_EQ(p->y(), q.y()) << "key " << key;
      EXPECT_EQ(p->rotation().c(), q.rotation().c()) << "key " << key;
      EXPECT_EQ(p->rotation().s(), q.rotation().s()) << "key " << key;
    } else if (const auto* p = std::get_if<Point2>(&x)) {
      EXPECT_EQ(p->x(), std::get<Point2>(y).x()) << "key " << key;
      EXPECT_EQ(p->y(), std::get<Point2>(y).y()) << "key " << key;
    } else {
      ADD_FAILURE() << "the demo log holds SE2 poses and Point2 landmarks only; key " << key;
    }
  }
}

SemanticSlamOptions mmNullHypothesis() {
  SemanticSlamOptions options;
  options.strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  return options;
}

TEST(SemanticSlamFork, ContinuesExactlyAsASingleRun) {
  // The demo's loop closures, look-alikes and clutter exercise every part of the front end that a fork must copy
  // (provisional landmarks, merges, the null escape's counters); the fork is taken mid-run, before the second lap.
  const MeasurementLog log = simulateDemoLog(3);
  const int steps = static_cast<int>(log.steps.size());
  const int forkAt = steps / 2;

  SemanticSlam single(log.header, mmNullHypothesis());
  for (const TimeStep& step : log.steps) single.addStep(step);
  const Outcome reference = outcomeOf(single);

  SemanticSlam original(log.header, mmNullHypothesis());
  for (int k = 0; k < forkAt; ++k) original.addStep(log.steps[k]);
  const std::unique_ptr<SemanticSlam> branch = original.fork();
  for (int k = forkAt; k < steps; ++k) {
    original.addStep(log.steps[k]);
    branch->addStep(log.steps[k]);
  }
  const Outcome fromOriginal = outcomeOf(original);
  const Outcome fromBranch = outcomeOf(*branch);

  ASSERT_GT(reference.landmarks, 0);
  for (const Outcome* outcome : {&fromOriginal, &fromBranch}) {
    EXPECT_EQ(outcome->associations, reference.associations);
    EXPECT_EQ(outcome->landmarks, reference.landmarks);
    expectSameEstimate(outcome->estimate, reference.estimate);
  }
}

TEST(SemanticSlamFork, IsIndependentOfTheOriginal) {
  // The branch sees a different future (the rest of the log without its detections); the original, fed the true
  // rest, must still give the single run's outcome, and the branch must differ from it.
  const MeasurementLog log = simulateDemoLog(3);
  const int steps = static_cast<int>(log.steps.size());
  const int forkAt = steps / 2;

  SemanticSlam single(log.header, mmNullHypothesis());
  for (const TimeStep& step : log.steps) single.addStep(step);
  const Outcome reference = outcomeOf(single);

  SemanticSlam original(log.header, mmNullHypothesis());
  for (int k = 0; k < forkAt; ++k) original.addStep(log.steps[k]);
  const std::unique_ptr<SemanticSlam> branch = original.fork();
  for (int k = forkAt; k < steps; ++k) {
    TimeStep blind = log.steps[k];
    blind.detections.clear();
    branch->addStep(blind);
  }
  for (int k = forkAt; k < steps; ++k) original.addStep(log.steps[k]);
  const Outcome fromOriginal = outcomeOf(original);
  const Outcome fromBranch = outcomeOf(*branch);

  EXPECT_EQ(fromOriginal.associations, reference.associations);
  expectSameEstimate(fromOriginal.estimate, reference.estimate);
  EXPECT_LT(fromBranch.associations.size(), reference.associations.size());
}

}  // namespace
}  // namespace semslam
