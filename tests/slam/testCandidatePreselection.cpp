// Spatial pre-selection in SemanticSlam (docs/association-front-end.md, §7): on seeded simulated runs, with and
// without pre-selection, ml, mm and mm-nh under both birth rules find the same candidates with the same weights,
// make the same decisions and end at the same estimate (to a tight tolerance: the joint marginal is taken over
// fewer variables, which changes its rounding, not its value). Same seed, same output bit for bit.

#include <gtest/gtest.h>

#include <random>

#include "semslam/sim/GeneratedPath.h"
#include "semslam/sim/SemanticSimulator.h"
#include "semslam/slam/SemanticSlam.h"

using namespace semslam;

namespace {

/// A single loop of `steps` metres with landmarks beside it: the map is several sensor ranges across, so most of
/// it is out of reach at any step (pre-selection has something to leave out), and the loop closes at the end.
MeasurementLog simulatedRun(int dimension, std::uint64_t seed) {
  PathOptions path;
  path.dimension = dimension;
  path.steps = 240;
  path.loops = 1;
  std::mt19937 rng(static_cast<unsigned>(seed));
  SemanticSimOptions options;
  options.classes = 3;
  options.landmarkDensity = 0.25;
  options.odomNoiseScale = 0.5;
  options.clutter = 0.3;
  options.misclassification = 0.1;
  return simulateSemantic(generatePath(path, rng), options, seed);
}

struct SlamRun {
  std::vector<DetectionRecord> records;
  RunResult result;
};

SlamRun run(const MeasurementLog& log, AssociationStrategy strategy, BirthRule birth, bool preselection) {
  SemanticSlamOptions options;
  options.strategy = strategy;
  options.birth = birth;
  options.candidatePreselection = preselection;
  SemanticSlam slam(log.header, options);
  for (const TimeStep& step : log.steps) slam.addStep(step);
  slam.finish();
  return {slam.detections(), slam.result(false)};
}

Vector positionOf(const Pose& pose) {
  if (const auto* se2 = std::get_if<SE2>(&pose)) return Vector3(se2->x(), se2->y(), se2->theta());
  const SE3& se3 = std::get<SE3>(pose);
  Vector v(6);
  v << se3.translation(), se3.rotation().matrix().col(0);
  return v;
}

Vector positionOf(const LandmarkState& state) {
  return std::visit([](const auto& s) -> Vector {
    using S = std::decay_t<decltype(s)>;
    if constexpr (std::is_same_v<S, Point2> || std::is_same_v<S, Point3>) return s;
    else return s.translation();
  }, state);
}

void expectSameRun(const SlamRun& preselected, const SlamRun& everyLandmark, const std::string& name) {
  ASSERT_EQ(preselected.records.size(), everyLandmark.records.size()) << name;
  int withCandidates = 0;
  for (std::size_t r = 0; r < preselected.records.size(); ++r) {
    const DetectionRecord& a = preselected.records[r];
    const DetectionRecord& b = everyLandmark.records[r];
    ASSERT_EQ(a.candidates, b.candidates) << name << " record " << r << " (step " << a.step << ")";
    ASSERT_EQ(a.createdLandmark, b.createdLandmark) << name << " record " << r;
    ASSERT_EQ(a.assigned, b.assigned) << name << " record " << r;
    ASSERT_EQ(a.weights.size(), b.weights.size());
    for (std::size_t c = 0; c < a.weights.size(); ++c) EXPECT_NEAR(a.weights[c], b.weights[c], 1e-9) << name;
    ASSERT_EQ(a.logLikelihoods.size(), b.logLikelihoods.size());
    for (std::size_t c = 0; c < a.logLikelihoods.size(); ++c) {
      EXPECT_NEAR(a.logLikelihoods[c], b.logLikelihoods[c], 1e-9 * (1.0 + std::abs(b.logLikelihoods[c]))) << name;
    }
    withCandidates += a.candidates.empty() ? 0 : 1;
  }
  EXPECT_GT(withCandidates, 100) << name;  // re-observations, not only births
  EXPECT_EQ(preselected.result.associations, everyLandmark.result.associations) << name;
  ASSERT_EQ(preselected.result.poses.size(), everyLandmark.result.poses.size());
  for (std::size_t k = 0; k < preselected.result.poses.size(); ++k) {
    EXPECT_LT((positionOf(preselected.result.poses[k]) - positionOf(everyLandmark.result.poses[k])).norm(), 1e-7)
        << name << " pose " << k;
  }
  ASSERT_EQ(preselected.result.landmarks.size(), everyLandmark.result.landmarks.size()) << name;
  for (std::size_t j = 0; j < preselected.result.landmarks.size(); ++j) {
    const Vector difference =
        positionOf(preselected.result.landmarks[j].state) - positionOf(everyLandmark.result.landmarks[j].state);
    EXPECT_LT(difference.norm(), 1e-7) << name << " landmark " << j;
  }
}

}  // namespace

TEST(CandidatePreselection, SameCandidatesWeightsAndEstimateAsTestingEveryLandmark) {
  for (int dimension : {2, 3}) {
    const MeasurementLog log = simulatedRun(dimension, 11);
    for (AssociationStrategy strategy : {AssociationStrategy::MaximumLikelihood, AssociationStrategy::MaxMixture,
                                         AssociationStrategy::MaxMixtureNullHypothesis}) {
      for (BirthRule birth : {BirthRule::Threshold, BirthRule::Unassigned}) {
        const std::string name = std::to_string(dimension) + "D " + strategyName(strategy) + " " + birthRuleName(birth);
        expectSameRun(run(log, strategy, birth, true), run(log, strategy, birth, false), name);
      }
    }
  }
}

TEST(CandidatePreselection, SameSeedSameOutputBitForBit) {
  const MeasurementLog log = simulatedRun(2, 4);
  const SlamRun first = run(log, AssociationStrategy::MaxMixtureNullHypothesis, BirthRule::Unassigned, true);
  const SlamRun second = run(log, AssociationStrategy::MaxMixtureNullHypothesis, BirthRule::Unassigned, true);
  ASSERT_EQ(first.records.size(), second.records.size());
  for (std::size_t r = 0; r < first.records.size(); ++r) {
    EXPECT_EQ(first.records[r].candidates, second.records[r].candidates);
    EXPECT_EQ(first.records[r].weights, second.records[r].weights);
  }
  for (std::size_t k = 0; k < first.result.poses.size(); ++k) {
    EXPECT_EQ(positionOf(first.result.poses[k]), positionOf(second.result.poses[k]));
  }
}
