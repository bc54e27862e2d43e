// SemanticSlam::fork(): an independent copy of a run, which continues exactly as a single run would.

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <vector>

#include "EstimateEquality.h"
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
  for (const DetectionRecord& record : slam.detections()) {
    outcome.associations.push_back(slam.chosenAssociation(record).first);
  }
  outcome.estimate = slam.smoother().estimate();
  outcome.landmarks = slam.landmarks();
  return outcome;
}

SemanticSlamOptions mmNullHypothesis() {
  SemanticSlamOptions options;
  options.strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  return options;
}

/// The demo's loop closures, look-alikes and clutter exercise most of the state a fork must copy (provisional
/// landmarks, merges, exclusion repairs, class beliefs); the fork is taken mid-run, where the second lap begins.
struct ForkedDemo {
  MeasurementLog log = simulateDemoLog(3);
  int steps = static_cast<int>(log.steps.size());
  int forkAt = steps / 2;
  Outcome reference;  // one run over every step
  SemanticSlam original{log.header, mmNullHypothesis()};
  std::unique_ptr<SemanticSlam> branch;  // forked from `original` after its first forkAt steps

  ForkedDemo() {
    SemanticSlam single(log.header, mmNullHypothesis());
    for (const TimeStep& step : log.steps) single.addStep(step);
    reference = outcomeOf(single);
    for (int k = 0; k < forkAt; ++k) original.addStep(log.steps[k]);
    branch = original.fork();
  }
};

TEST(SemanticSlamFork, ContinuesExactlyAsASingleRun) {
  ForkedDemo demo;
  for (int k = demo.forkAt; k < demo.steps; ++k) {
    demo.original.addStep(demo.log.steps[k]);
    demo.branch->addStep(demo.log.steps[k]);
  }
  const Outcome fromOriginal = outcomeOf(demo.original);
  const Outcome fromBranch = outcomeOf(*demo.branch);

  ASSERT_GT(demo.reference.landmarks, 0);
  for (const Outcome* outcome : {&fromOriginal, &fromBranch}) {
    EXPECT_EQ(outcome->associations, demo.reference.associations);
    EXPECT_EQ(outcome->landmarks, demo.reference.landmarks);
    expectSameEstimate(outcome->estimate, demo.reference.estimate);
  }
}

TEST(SemanticSlamFork, IsIndependentOfTheOriginal) {
  // The branch sees a different future (the rest of the log without its detections), first; the original, fed the
  // true rest afterwards, must still give the single run's outcome.
  ForkedDemo demo;
  for (int k = demo.forkAt; k < demo.steps; ++k) {
    TimeStep blind = demo.log.steps[k];
    blind.detections.clear();
    demo.branch->addStep(blind);
  }
  for (int k = demo.forkAt; k < demo.steps; ++k) demo.original.addStep(demo.log.steps[k]);
  const Outcome fromOriginal = outcomeOf(demo.original);
  const Outcome fromBranch = outcomeOf(*demo.branch);

  EXPECT_EQ(fromOriginal.associations, demo.reference.associations);
  expectSameEstimate(fromOriginal.estimate, demo.reference.estimate);
  EXPECT_LT(fromBranch.associations.size(), demo.reference.associations.size());
}

}  // namespace
}  // namespace semslam
