// Two branches at an ambiguous loop closure (slam/LoopClosureBranches.h, docs/association-front-end.md §10).
//
// The scenario: a constellation of two objects, A and D, has a look-alike, B and E, the same two objects 0.8 m
// further along y; a third object, F, has none. The robot maps A, D and F from a standstill, drives 20 m away and
// back on odometry that is exact but declared uncertain (σ 0.5 m per 2 m step; detections σ 0.3 m), and on its
// return first sees only the look-alikes: their pairing with A and D is inside the gate, far likelier than two new
// objects and anchoring (the pose is known to 2 m, the detections to 0.3 m), so the front end closes the loop on
// the wrong constellation. The next step sees A and D themselves 0.8 m from where that closure puts them, and
// their look-alikes where it expects A and D: A and D start new landmarks, and the error stays. With a second
// branch open for a few steps, the branch that kept B and E apart sees A, D and F re-sighted where they are
// mapped, and its evidence wins.
//
// The third branch's scenario (mm-nh's default, --loop-closure-next-best for ml; run with ml, whose pairings stay
// as the step made them): all five objects are mapped from the standstill, and the odometry back slips 0.8 m along
// y (within its declared σ), so that A and D, seen alone on the return, appear where B and E are mapped: the front
// end pairs them with B's and E's landmarks. Keeping them apart makes two duplicates; pairing them with their
// next-best landmarks, A's and D's own, is right, and its evidence wins once F is re-sighted.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <vector>
#include <stdexcept>

#include "EstimateEquality.h"
#include "semslam/slam/BranchScore.h"
#include "semslam/slam/LoopClosureBranches.h"

namespace semslam {
namespace {

constexpr int kA = 0, kD = 1, kF = 2, kB = 3, kE = 4;  // truth ids

struct LookAlikes {
  LogHeader header;
  std::vector<Point2> objects{Point2(6.0, 0.0), Point2(4.0, -5.0), Point2(-3.0, 6.0),  // A, D, F
                              Point2(6.0, 0.8), Point2(4.0, -4.2)};                    // B = A + s, E = D + s
  double travelSigma;  // of each 2 m step of the drive away and back
  bool lookAlikesMapped = false;  // B and E seen from the standstill too (the third branch's scenario)
  double slip = 0.0;              // the odometry's error along y over the drive back (exact when 0)
  static constexpr int kMapping = 4, kAway = 10, kBack = 10;  // steps: mapping at a standstill, away, back
  static constexpr int kReturn = kMapping + kAway + kBack;    // the first step back: B and E alone (A and D with
                                                              // lookAlikesMapped)

  explicit LookAlikes(double travelSigma = 0.5) : travelSigma(travelSigma) {
    header.sensor.kind = SensorKind::RelativePosition;
    header.sensor.maxRange = 30.0;
    header.sensor.fieldOfView = 2.0 * std::numbers::pi;
    header.initialPose = PosePrior{SE2(), Vector3(1e-6, 1e-6, 1e-8).asDiagonal().toDenseMatrix()};
  }

  /// At 0 while mapping, out along −x by 2 m a step, back, and at a standstill from kReturn on.
  static double x(int k) {
    if (k < kMapping) return 0.0;
    if (k < kMapping + kAway) return -2.0 * (k - kMapping + 1);
    return -2.0 * kAway + 2.0 * (std::min(k, kReturn) - kMapping - kAway);
  }

  std::vector<int> seen(int k) const {
    if (k < kMapping) return lookAlikesMapped ? std::vector<int>{kA, kD, kF, kB, kE} : std::vector<int>{kA, kD, kF};
    if (k < kReturn) return {};
    if (k == kReturn) return lookAlikesMapped ? std::vector<int>{kA, kD} : std::vector<int>{kB, kE};
    return {kA, kD, kF, kB, kE};
  }

  TimeStep step(int k) const {
    TimeStep s;
    s.time = k;
    s.truePose = SE2(x(k), 0.0, 0.0);
    if (k > 0) {
      const double sigma = x(k) != x(k - 1) ? travelSigma : 0.01, headingSigma = 0.02 * sigma;
      const bool back = k > kMapping + kAway && k <= kReturn;
      s.odometry = Odometry{SE2(x(k) - x(k - 1), back ? slip / kBack : 0.0, 0.0),
                            Vector3(sigma * sigma, sigma * sigma, headingSigma * headingSigma).asDiagonal().toDenseMatrix()};
    }
    for (int id : seen(k)) {
      Detection d;
      d.geometry = SE2(x(k), 0.0, 0.0).transformTo(objects[static_cast<std::size_t>(id)]);
      d.covariance = 0.3 * 0.3 * Matrix::Identity(2, 2);
      d.truthId = id;
      s.detections.push_back(d);
    }
    return s;
  }
};

SemanticSlamOptions optionsWithWindow(int window) {
  SemanticSlamOptions options;
  options.loopClosureBranchWindow = window;
  return options;
}

/// The landmark each truth id's detections end on, where they all end on one; -1 where they are split or on none.
std::map<int, int> landmarkOfTruth(const SemanticSlam& slam) {
  std::map<int, std::set<std::optional<int>>> on;
  for (const DetectionRecord& record : slam.detections()) on[*record.truth].insert(slam.chosenAssociation(record).first);
  std::map<int, int> landmark;
  for (const auto& [truth, landmarks] : on) {
    landmark[truth] = landmarks.size() == 1 && *landmarks.begin() ? **landmarks.begin() : -1;
  }
  return landmark;
}

/// Each of the scenario's five objects has all its detections on one landmark, and no two share one.
void expectEveryObjectOnALandmarkOfItsOwn(const SemanticSlam& slam) {
  const std::map<int, int> landmarks = landmarkOfTruth(slam);
  ASSERT_EQ(landmarks.size(), 5u);
  std::set<int> distinct;
  for (const auto& [truth, landmark] : landmarks) {
    EXPECT_GE(landmark, 0) << "object " << truth;
    distinct.insert(landmark);
  }
  EXPECT_EQ(distinct.size(), 5u);
}

/// The scenario under mm-nh with two branches (A and B) and one split at a time (the third branch and splits within
/// splits, mm-nh's defaults, are tested on their own below).
LoopClosureBranches runScenario(int window, int steps, double travelSigma = 0.5) {
  const LookAlikes scenario(travelSigma);
  SemanticSlamOptions options = optionsWithWindow(window);
  options.loopClosureNextBest = false;
  options.loopClosureOpenSplits = 1;
  LoopClosureBranches run(scenario.header, options);
  for (int k = 0; k < steps; ++k) run.addStep(scenario.step(k));
  run.finish();
  return run;
}

constexpr int kSteps = LookAlikes::kReturn + 5;

/// The record of object `truth`'s detection at `step`.
const DetectionRecord& recordOf(const SemanticSlam& slam, int step, int truth) {
  for (const DetectionRecord& record : slam.detections()) {
    if (record.step == step && record.truth == truth) return record;
  }
  throw std::logic_error("no such detection");
}

TEST(LoopClosureBranches, WithoutABranchTheLookAlikeClosesTheLoopOnTheWrongObject) {
  const LoopClosureBranches run = runScenario(0, kSteps);
  EXPECT_TRUE(run.splits().empty());
  // B's first detection ends on the landmark A's first detection started: the failure the branches are for.
  const SemanticSlam& slam = run.slam();
  const std::optional<int> landmarkOfA = slam.chosenAssociation(recordOf(slam, 0, kA)).first;
  ASSERT_TRUE(landmarkOfA);
  EXPECT_EQ(slam.chosenAssociation(recordOf(slam, LookAlikes::kReturn, kB)).first, landmarkOfA);
}

TEST(LoopClosureBranches, ABranchOpenUntilTheTrueObjectIsReSeenKeepsTheLookAlikeApart) {
  const LoopClosureBranches run = runScenario(3, kSteps);
  ASSERT_EQ(run.splits().size(), 1u);
  const LoopClosureBranches::Split& split = run.splits().front();
  EXPECT_EQ(split.openedAt, LookAlikes::kReturn);
  EXPECT_EQ(split.closedAfter, LookAlikes::kReturn + 3);
  EXPECT_EQ(split.kept, LoopClosureBranches::Branch::Apart);
  EXPECT_LT(split.scoreB, split.scoreA);
  EXPECT_FALSE(split.scoreC);  // turned off
  // Every object's detections on one landmark of their own.
  expectEveryObjectOnALandmarkOfItsOwn(run.slam());
}

// μ estimated from the run (UnassignedHypothesis.h): branch B starts landmarks where A pairs, so the two runs'
// estimates part at the split; both are scored at the μ of the history they share, the run's before the step that
// opened the split (docs/association-front-end.md §10, "μ from the run").
TEST(LoopClosureBranches, WithAnEstimatedRateTheBranchesAreScoredAtTheRateBeforeTheSplit) {
  const LookAlikes scenario;
  SemanticSlamOptions options = optionsWithWindow(3);
  options.loopClosureNextBest = false;
  options.loopClosureOpenSplits = 1;
  options.unassignedRateWeight = 5.0;
  LoopClosureBranches run(scenario.header, options);
  for (int k = 0; k < LookAlikes::kReturn; ++k) run.addStep(scenario.step(k));
  const double rateBeforeSplit = run.slam().unassignedHypothesis().rate();
  for (int k = LookAlikes::kReturn; k <= LookAlikes::kReturn + 3; ++k) run.addStep(scenario.step(k));
  ASSERT_EQ(run.splits().size(), 1u);  // closed by the last step, the kept run not moved since
  const LoopClosureBranches::Split& split = run.splits().front();
  ASSERT_EQ(split.kept, LoopClosureBranches::Branch::Apart);
  EXPECT_NE(run.slam().unassignedHypothesis().rate(), rateBeforeSplit);
  EXPECT_EQ(split.scoreB, branchScore(run.slam(), rateBeforeSplit));
  EXPECT_GT(std::abs(branchScore(run.slam()) - split.scoreB), 10.0 * kBranchScoreTolerance);
}

/// The third branch's scenario: ml (one landmark per detection, so a pairing stays as the step made it; under mm-nh
/// the return's mixtures switch to A's and D's landmarks once F pins the pose).
SemanticSlamOptions slipOptions(int window, bool nextBest) {
  SemanticSlamOptions options = optionsWithWindow(window);  // splits open at a time: the default
  options.strategy = AssociationStrategy::MaximumLikelihood;
  options.loopClosureNextBest = nextBest;
  return options;
}

/// The third branch's scenario run with `options`.
LoopClosureBranches runSlipScenario(const SemanticSlamOptions& options) {
  LookAlikes scenario;
  scenario.lookAlikesMapped = true;
  scenario.slip = 0.8;
  LoopClosureBranches run(scenario.header, options);
  for (int k = 0; k < kSteps; ++k) run.addStep(scenario.step(k));
  run.finish();
  return run;
}

TEST(LoopClosureBranches, WithoutTheThirdBranchTheSlipPairsEachObjectWithItsLookAlike) {
  for (const bool branches : {false, true}) {
    const LoopClosureBranches run = runSlipScenario(slipOptions(branches ? 3 : 0, false));
    const SemanticSlam& slam = run.slam();
    const std::optional<int> landmarkOfB = slam.chosenAssociation(recordOf(slam, 0, kB)).first;
    const std::optional<int> landmarkOfA = slam.chosenAssociation(recordOf(slam, 0, kA)).first;
    ASSERT_TRUE(landmarkOfA && landmarkOfB);
    const std::optional<int> returned = slam.chosenAssociation(recordOf(slam, LookAlikes::kReturn, kA)).first;
    EXPECT_NE(returned, landmarkOfA) << (branches ? "with" : "without") << " branches";
    if (!branches) EXPECT_EQ(returned, landmarkOfB);  // the look-alike's landmark, where the slip puts A
  }
}

TEST(LoopClosureBranches, TheThirdBranchPairsTheReturnWithTheNextBestLandmarksAndWins) {
  const LoopClosureBranches run = runSlipScenario(slipOptions(3, true));
  ASSERT_EQ(run.splits().size(), 1u);
  const LoopClosureBranches::Split& split = run.splits().front();
  EXPECT_EQ(split.openedAt, LookAlikes::kReturn);
  ASSERT_TRUE(split.scoreC);
  EXPECT_EQ(split.kept, LoopClosureBranches::Branch::NextBest);
  EXPECT_LT(*split.scoreC, split.scoreA);
  EXPECT_LT(*split.scoreC, split.scoreB);
  // Every object's detections, the return's included, on one landmark of their own.
  expectEveryObjectOnALandmarkOfItsOwn(run.slam());
}

TEST(LoopClosureBranches, PairElsewhereTakesTheNextBestLandmarkOrReportsThatThereIsNone) {
  LookAlikes scenario;
  scenario.lookAlikesMapped = true;
  scenario.slip = 0.8;
  SemanticSlam slam(scenario.header, slipOptions(0, false));
  for (int k = 0; k < LookAlikes::kReturn; ++k) slam.addStep(scenario.step(k));
  slam.beginStep(scenario.step(LookAlikes::kReturn));
  const std::vector<std::size_t> anchoring = slam.anchoringDetections();
  ASSERT_EQ(anchoring.size(), 2u);  // A and D, paired with B's and E's landmarks
  const std::size_t first = anchoring.front();
  EXPECT_THROW(slam.pairElsewhere({first - 1}), std::invalid_argument);  // a record of an earlier step
  std::unique_ptr<SemanticSlam> elsewhere = slam.fork();
  ASSERT_TRUE(elsewhere->pairElsewhere(anchoring));
  elsewhere->completeStep();
  const std::optional<int> landmarkOfA = elsewhere->chosenAssociation(recordOf(*elsewhere, 0, kA)).first;
  const std::optional<int> landmarkOfD = elsewhere->chosenAssociation(recordOf(*elsewhere, 0, kD)).first;
  EXPECT_EQ(elsewhere->chosenAssociation(recordOf(*elsewhere, LookAlikes::kReturn, kA)).first, landmarkOfA);
  EXPECT_EQ(elsewhere->chosenAssociation(recordOf(*elsewhere, LookAlikes::kReturn, kD)).first, landmarkOfD);
  // Each call takes from each record the landmark it was paired with; once the unassigned hypothesis is next for
  // both, it says so, and the records start landmarks of their own. A call that pairs either record takes at least
  // one candidate away, so the calls end within the records' candidates.
  std::size_t candidates = 0;
  for (std::size_t r : anchoring) candidates += slam.detections()[r].candidates.size();
  std::unique_ptr<SemanticSlam> again = slam.fork();
  std::size_t calls = 1;
  while (again->pairElsewhere(anchoring)) ASSERT_LE(++calls, candidates + 1);
  EXPECT_GE(calls, 2u);
  again->completeStep();
  EXPECT_TRUE(recordOf(*again, LookAlikes::kReturn, kA).createdLandmark);
  EXPECT_TRUE(recordOf(*again, LookAlikes::kReturn, kD).createdLandmark);
  slam.completeStep();  // the run itself is unchanged by its forks
  EXPECT_NE(slam.chosenAssociation(recordOf(slam, LookAlikes::kReturn, kA)).first, landmarkOfA);
}

TEST(LoopClosureBranches, ARunWithoutAnAnchoringPairingIsTheSingleRunBitForBit) {
  // Precise odometry: every pairing is made from a well-known pose (and the look-alikes start landmarks of their
  // own), so no split opens.
  const LookAlikes scenario(0.01);
  const LoopClosureBranches branched = runScenario(16, kSteps, scenario.travelSigma);
  ASSERT_TRUE(branched.splits().empty());
  SemanticSlam single(scenario.header, optionsWithWindow(0));
  for (int k = 0; k < kSteps; ++k) single.addStep(scenario.step(k));
  single.finish();
  expectSameEstimate(branched.slam().smoother().estimate(), single.smoother().estimate());
  ASSERT_EQ(branched.slam().detections().size(), single.detections().size());
  for (std::size_t r = 0; r < single.detections().size(); ++r) {
    EXPECT_EQ(branched.slam().chosenAssociation(branched.slam().detections()[r]).first,
              single.chosenAssociation(single.detections()[r]).first);
  }
}

TEST(LoopClosureBranches, AWindowNeedsTheJointAssignmentAndFactorsThatAreTheLikelihood) {
  for (const AssociationStrategy strategy : {AssociationStrategy::Known, AssociationStrategy::Gpda}) {
    SemanticSlamOptions options = optionsWithWindow(4);
    options.strategy = strategy;
    EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument) << strategyName(strategy);
  }
  SemanticSlamOptions options = optionsWithWindow(4);
  options.birth = BirthRule::Threshold;
  EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument);
  options = optionsWithWindow(-1);
  EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument);
  // The next-best branch is a third branch of a split: it needs splits.
  options = optionsWithWindow(0);
  options.loopClosureNextBest = true;
  EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument);
  options = SemanticSlamOptions{};
  options.strategy = AssociationStrategy::Gpda;
  options.loopClosureNextBest = true;
  EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument);
  options.strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  EXPECT_EQ(LoopClosureBranches::window(options), LoopClosureBranches::kDefaultWindow);
}

/// The default options with each strategy and each birth rule.
std::vector<SemanticSlamOptions> everyStrategyAndBirthRule() {
  std::vector<SemanticSlamOptions> all;
  for (const AssociationStrategy strategy : allStrategies()) {
    for (const BirthRule birth : {BirthRule::Unassigned, BirthRule::Threshold}) {
      SemanticSlamOptions options;
      options.strategy = strategy;
      options.birth = birth;
      all.push_back(options);
    }
  }
  return all;
}

TEST(LoopClosureBranches, TheDefaultWindowIsOnWhereBranchesApplyAndOffElsewhere) {
  for (SemanticSlamOptions options : everyStrategyAndBirthRule()) {
    const AssociationStrategy strategy = options.strategy;
    const bool applies = options.birth == BirthRule::Unassigned && strategy != AssociationStrategy::Known &&
                         strategy != AssociationStrategy::Gpda;
    EXPECT_EQ(LoopClosureBranches::window(options), applies ? LoopClosureBranches::kDefaultWindow : 0)
        << strategyName(strategy);
    options.loopClosureBranchWindow = 0;  // off is accepted everywhere
    EXPECT_EQ(LoopClosureBranches::window(options), 0);
  }
  // With the default options, the scenario's loop closure opens a split, and branch B's re-sighting of A, D and F
  // one step later a second one inside it (the test above keeps the look-alike apart with a window of 3, two
  // branches and one split at a time).
  const LookAlikes scenario;
  LoopClosureBranches run(scenario.header, SemanticSlamOptions{});
  for (int k = 0; k < kSteps; ++k) run.addStep(scenario.step(k));
  run.finish();
  ASSERT_EQ(run.splits().size(), 2u);
  EXPECT_EQ(run.splits()[0].openedAt, LookAlikes::kReturn);
  EXPECT_EQ(run.splits()[1].openedAt, LookAlikes::kReturn + 1);
}

TEST(LoopClosureBranches, TheNextBestBranchIsMmNhsDefaultWhereItHasBranches) {
  for (SemanticSlamOptions options : everyStrategyAndBirthRule()) {
    const AssociationStrategy strategy = options.strategy;
    const bool branches = LoopClosureBranches::window(options) > 0;
    EXPECT_EQ(LoopClosureBranches::nextBest(options),
              branches && strategy == AssociationStrategy::MaxMixtureNullHypothesis)
        << strategyName(strategy);
    options.loopClosureBranchWindow = 0;  // no branches: no third one, and the unset default is not refused
    EXPECT_FALSE(LoopClosureBranches::nextBest(options)) << strategyName(strategy);
    options.loopClosureBranchWindow.reset();
    if (!branches) continue;
    options.loopClosureNextBest = false;  // an explicit choice holds for every method with branches
    EXPECT_FALSE(LoopClosureBranches::nextBest(options)) << strategyName(strategy);
    options.loopClosureNextBest = true;
    EXPECT_TRUE(LoopClosureBranches::nextBest(options)) << strategyName(strategy);
  }
}

TEST(LoopClosureBranches, MmNhOpensTheNextBestBranchByDefault) {
  // The slip scenario of the third branch's tests, under mm-nh with its defaults: the split opens all three.
  const LoopClosureBranches run = runSlipScenario(SemanticSlamOptions{});
  ASSERT_FALSE(run.splits().empty());
  EXPECT_TRUE(run.splits().front().scoreC);
}


/// A run of `scenario` with `options`, and the number of open branches after each step.
struct TracedRun {
  LoopClosureBranches run;
  std::vector<std::size_t> openBranches;
};

TracedRun runTraced(const LookAlikes& scenario, const SemanticSlamOptions& options) {
  TracedRun traced{LoopClosureBranches(scenario.header, options), {}};
  for (int k = 0; k < kSteps; ++k) {
    traced.run.addStep(scenario.step(k));
    traced.openBranches.push_back(traced.run.openBranches());
  }
  traced.run.finish();
  return traced;
}

TEST(LoopClosureBranches, WithTwoOpenSplitsABranchSplitsAgainAndEachSplitKeepsItsLowestLeaf) {
  // The first scenario, two branches per split. Branch B of the return's split kept the look-alikes apart, so at
  // the next step its re-sightings of A, D and F, made from a pose known to 2 m, anchor: with one split at a time
  // they are decided as without branches; with two, branch B splits again.
  const LookAlikes scenario;
  SemanticSlamOptions options = optionsWithWindow(3);
  options.loopClosureNextBest = false;
  options.loopClosureOpenSplits = 1;
  const TracedRun one = runTraced(scenario, options);
  options.loopClosureOpenSplits = 2;
  const TracedRun two = runTraced(scenario, options);
  const int k = LookAlikes::kReturn;
  EXPECT_EQ(*std::max_element(one.openBranches.begin(), one.openBranches.end()), 2u);
  EXPECT_EQ(std::vector<std::size_t>(two.openBranches.begin() + k - 1, two.openBranches.begin() + k + 5),
            (std::vector<std::size_t>{1, 2, 3, 3, 2, 1}));  // the second split closes with the log's last step
  ASSERT_EQ(one.run.splits().size(), 1u);
  ASSERT_EQ(two.run.splits().size(), 2u);
  EXPECT_EQ(two.run.splits()[0].openedAt, k);
  EXPECT_EQ(two.run.splits()[1].openedAt, k + 1);
  for (const LoopClosureBranches::Split& split : two.run.splits()) {
    EXPECT_EQ(split.closedAfter, split.openedAt + 3);
    EXPECT_EQ(split.kept, split.scoreB < split.scoreA ? LoopClosureBranches::Branch::Apart
                                                       : LoopClosureBranches::Branch::AsIs);
  }
  // The outer split sees branch B through its lowest leaf, which at its close is the inner split's branch A: the
  // run of one split at a time, whose score it is, bit for bit.
  EXPECT_EQ(two.run.splits()[0].scoreB, one.run.splits()[0].scoreB);
  EXPECT_EQ(two.run.splits()[0].kept, LoopClosureBranches::Branch::Apart);
  EXPECT_EQ(two.run.splits()[1].kept, LoopClosureBranches::Branch::AsIs);
  expectSameEstimate(two.run.slam().smoother().estimate(), one.run.slam().smoother().estimate());
  expectEveryObjectOnALandmarkOfItsOwn(two.run.slam());
}

TEST(LoopClosureBranches, ASplitOpenOnlyInADroppedBranchIsDroppedWithIt) {
  // The third branch's scenario with two open splits: a second split opens inside the return's split (five open
  // branches), then the return's split keeps its third branch, in which none opened: the inner split goes with the
  // branch it opened in, is not listed, and the run is that of one split at a time, bit for bit.
  LookAlikes scenario;
  scenario.lookAlikesMapped = true;
  scenario.slip = 0.8;
  SemanticSlamOptions options = slipOptions(3, true);
  options.loopClosureOpenSplits = 1;
  const TracedRun one = runTraced(scenario, options);
  options.loopClosureOpenSplits = 2;
  const TracedRun two = runTraced(scenario, options);
  const int k = LookAlikes::kReturn;
  EXPECT_EQ(std::vector<std::size_t>(two.openBranches.begin() + k - 1, two.openBranches.begin() + k + 4),
            (std::vector<std::size_t>{1, 3, 5, 5, 1}));
  ASSERT_EQ(two.run.splits().size(), 1u);
  EXPECT_EQ(two.run.splits()[0].kept, LoopClosureBranches::Branch::NextBest);
  EXPECT_EQ(two.run.splits()[0].scoreC, one.run.splits()[0].scoreC);
  expectSameEstimate(two.run.slam().smoother().estimate(), one.run.slam().smoother().estimate());
}

TEST(LoopClosureBranches, TwoOpenSplitsAreTheDefaultWhereBranchesApply) {
  for (SemanticSlamOptions options : everyStrategyAndBirthRule()) {
    const bool branches = LoopClosureBranches::window(options) > 0;
    EXPECT_EQ(LoopClosureBranches::maximumOpenSplits(options), branches ? LoopClosureBranches::kDefaultOpenSplits : 1)
        << strategyName(options.strategy);
    options.loopClosureOpenSplits = 1;
    EXPECT_EQ(LoopClosureBranches::maximumOpenSplits(options), 1);
    options.loopClosureBranchWindow = 0;  // no branches: one "split" at most, as asked or by default
    options.loopClosureNextBest.reset();
    EXPECT_EQ(LoopClosureBranches::maximumOpenSplits(options), 1);
    options.loopClosureOpenSplits.reset();
    EXPECT_EQ(LoopClosureBranches::maximumOpenSplits(options), 1);
  }
}

TEST(LoopClosureBranches, OpenSplitsAreAtLeastOneAndMoreThanOneNeedBranches) {
  SemanticSlamOptions options;
  options.loopClosureOpenSplits = 0;
  EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument);
  options.loopClosureOpenSplits = 2;
  EXPECT_EQ(LoopClosureBranches::maximumOpenSplits(options), 2);
  options.loopClosureBranchWindow = 0;
  EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument);
  options = SemanticSlamOptions{};
  options.strategy = AssociationStrategy::Gpda;
  options.loopClosureOpenSplits = 2;
  EXPECT_THROW(LoopClosureBranches(LookAlikes().header, options), std::invalid_argument);
}

}  // namespace
}  // namespace semslam
