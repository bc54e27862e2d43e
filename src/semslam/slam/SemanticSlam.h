#pragma once
// SemanticSlam: paper B's pipeline (sec. IV) with any of the five association strategies (AssociationStrategy.h),
// fed one log step at a time, on any Smoother back end.
//
// Per step k (B, sec. IV-A):
//   1. propagate: pose x_k enters at x_{k−1} ⊕ odometry with its odometry factor (step 0: the log's pose prior,
//      or a gauge prior σ = 1e-6 at the identity when it has none; the log's map priors enter as landmarks);
//      the smoother re-solves, so the marginals below include x_k;
//   2. candidates (B, sec. IV-B): for each detection z and landmark l, the linearised marginal likelihood
//          p_geo(z | l) = N(z; h(x̄_k, l̄), H Σ_joint Hᵀ + R),  Σ_joint = Cov([x_k; l])  (MarginalLikelihood.h)
//      and l is a candidate when its innovation chi2 passes the gate (AssociationGate.h); only the landmarks that can
//      pass are tested, found through a grid (CandidatePreselection.h, docs/association-front-end.md §7), and
//      Σ_joint comes from one joint marginal over x_k and those landmarks. A candidate's weight is
//          w_l ∝ p_geo(z | l) · Σ_c P(z_sem | c) P(c | l)            (ClassBelief.h)
//      normalised over the candidates. No candidate: z starts a new landmark at its back-projection from x̄_k;
//      with BirthRule::Unassigned (docs/association-front-end.md) the gate is the joint geometric × semantic one,
//      every detection also has the unassigned hypothesis (UnassignedHypothesis.h), and the step's detections are
//      assigned jointly, at most one per landmark, by the joint density of the step's pairings (the default,
//      AssignmentScore::Joint, JointCompatibility.h; AssignmentScore::Independent: Hungarian on each pairing's own
//      likelihood); an unassigned detection starts a new landmark
//      (a posed landmark seen by a position-only sensor also gets a prior of σ = π on its orientation, which
//      nothing else observes, and an uninformative one on its position, so the system stays positive definite);
//   3. the strategy's factors (AssociationStrategy.h): mm builds a MaxMixtureFactor with components w_l; mm-nh adds
//      the null hypothesis, the detection's factor to the most likely candidate (with BirthRule::Unassigned: the
//      jointly assigned landmark, which the warm start below uses too) with standard deviations scaled by
//      nullSigmaScale, with weight nullWeight (the candidates share 1 − nullWeight); gpda adds one factor per
//      candidate whose information is scaled by w_l;
//   4. the smoother re-solves (mm, mm-nh with warmStart: first with each detection's most likely candidate, then
//      again with the mixtures, so that they choose their components near the step's solution rather than at the
//      odometry prediction, where the null hypothesis would win every detection once the odometry is poor; only
//      for a detection whose best candidate is unambiguous, warmStartMinimumPosterior); gpda runs emIterations
//      E-steps over the detections of the last emWindow steps
//      (weights recomputed at the current estimate, Σ_joint = 0, i.e. N(z; h(X̂), R) times the semantic term, the
//      same likelihood code with no state uncertainty) and M-steps (factors replaced, re-solve);
//   5. class beliefs: each candidate's P(c | l) is updated with the detection's class likelihoods, tempered by its
//      association weight (ClassBelief.h);
//   6. with BirthRule::Unassigned, the landmarks' lifecycle (docs/association-front-end.md §5): a landmark born
//      from an unassigned detection is provisional (a weak prior, σ = r_max per axis, keeps it well-posed whatever
//      happens to its detections) until the M-of-N rule (LandmarkLifecycle.h) confirms it (its prior is removed),
//      drops it (its detections are left on no landmark) or a merge test puts it into a mapped landmark (its
//      detections move there); a confirmed landmark seen at the step is tested the same way against the other
//      confirmed ones, and of a duplicate pair the newer merges into the older (§5c; its variable gets the weak
//      prior back); the graph edits of a step are one smoother update; with labelSplit, a landmark seen at the step
//      whose labels say it holds two objects then splits (§5d, LandmarkSplit.h; one more update). Then exclusion is
//      repaired (§4): while two of the step's mixtures use one landmark at the estimate, the worse of them loses
//      that component, and the step is re-solved. finish() drops what is still provisional and repairs every step;
//   7. mm-nh with nullEscape (docs/association-front-end.md §6b): for each landmark seen at the step, the
//      detections the front end put on it whose mixture sits on its null component at the estimate, if there are
//      at least two (one is what the null hypothesis is for), are tried on the landmark together in a fork of the
//      smoother (their plain factors, converge, the mixtures back, converge); the fork replaces the smoother when
//      the graph's cost there, the max-mixture objective F = ½ Σ chi2 with every mixture at its own choice, is
//      not above the cost of the unchanged graph converged alike (within kEscapeTolerance, the roundoff band of
//      two converged costs: a trial that converges back to the same optimum is a tie, kept, and the landmark may
//      be tried again; §6b, "Ties, kept on purpose"). Each acceptance lowers F or leaves it where it was,
//      converged: the escape only ever moves the estimate to a better optimum of paper B's own objective, out of
//      the basin where a drifted estimate has put a landmark's re-sightings beyond the null hypothesis's
//      break-even and nothing pulls it back.
//      With nullEscapeWindow T > 0 (§6c), a single detection on null is tried as well when the landmark had a
//      detection off null at most T seconds before it: within a tracked object's stream of sightings, one on null
//      says the estimate lags, as two do; after a long gap a lone detection stays what the null hypothesis is for.
// Decisions where paper B is silent are in docs/max-mixtures.md.
//
// With decideOnTrueHistory (decisions on the true history, docs/association-front-end.md §8b) the graph is
// `known`'s and steps 1-2 run only to record the front end's decision on each detection (DetectionRecord::decided),
// never applied.
//
// A step is processed in two halves, beginStep (steps 1-2, the joint assignment found but not applied) and
// completeStep (the rest), so that a run can be forked between them with a different decision on the step's
// anchoring pairings (keepApart, pairElsewhere) and anchoring merges (keepMergesApart): LoopClosureBranches.h
// keeps two or three such branches and the one the data favour (docs/association-front-end.md §10). addStep is the
// two halves in one.
//
// Invariants: landmark indices are dense, 0-based, in creation order, and are the landmark ids of every output
// (a dropped or merged landmark keeps its index and its variable, held by its weak prior, but leaves the map and
// every candidate list); every detection of every step processed has exactly one DetectionRecord; a record's
// `factors` are exactly the smoother factors in force for its detection.

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/CandidatePreselection.h"
#include "semslam/association/ClassBelief.h"
#include "semslam/association/LandmarkLifecycle.h"
#include "semslam/association/MeasurementFactory.h"
#include "semslam/association/UnassignedHypothesis.h"
#include "semslam/models/RunResult.h"
#include "semslam/slam/AssociationStrategy.h"
#include "semslam/slam/MixtureChoiceCache.h"
#include "semslam/solve/SmootherFactory.h"

namespace semslam {

/// How a detection that matches no mapped landmark starts one (docs/association-front-end.md).
enum class BirthRule {
  Threshold,   ///< paper B: a landmark starts when no landmark passes the geometric gate
  Unassigned,  ///< the default: every detection also has the unassigned hypothesis (UnassignedHypothesis.h); the
               ///< step's detections are assigned jointly, one per landmark (Hungarian), under the joint gate;
               ///< new landmarks are provisional (LandmarkLifecycle.h)
};

/// "threshold" | "unassigned"; anything else throws std::invalid_argument.
BirthRule parseBirthRule(const std::string& name);
std::string birthRuleName(BirthRule rule);

/// How the joint assignment of a step (BirthRule::Unassigned) scores an association of its detections
/// (docs/association-front-end.md §4).
enum class AssignmentScore {
  Independent,  ///< each pairing by its own marginal density, the product maximised by the Hungarian algorithm
  Joint,        ///< the pairings by the joint density of their stacked innovations, which share the pose's error
                ///< (association/JointCompatibility.h: joint compatibility branch and bound; the default since
                ///< session 33, §4 "The default")
};

/// "independent" | "joint"; anything else throws std::invalid_argument.
AssignmentScore parseAssignmentScore(const std::string& name);
std::string assignmentScoreName(AssignmentScore score);

struct SemanticSlamOptions {
  AssociationStrategy strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  BirthRule birth = BirthRule::Unassigned;  ///< the default since issue 10 (docs/association-front-end.md §9)
  double unassignedRate = UnassignedHypothesis::kDefaultRate;  ///< μ: unassigned detections expected per step
  /// Where set, μ is estimated from the run with this prior weight, in steps, on unassignedRate
  /// (UnassignedHypothesis.h; docs/association-front-end.md §10, "μ from the run"); unset, μ is unassignedRate.
  std::optional<double> unassignedRateWeight;
  /// With unassignedRateWeight: the estimate's memory in steps, its counts discounted by 1 − 1/M a step
  /// (UnassignedHypothesis.h; docs/association-front-end.md §10, "μ from the run, with a memory"); unset: every step
  /// counts alike.
  std::optional<double> unassignedRateMemory;
  double gateConfidence = AssociationGate::kDefaultConfidence;
  double nullWeight = 0.1;        ///< mm-nh: weight of the null hypothesis (B, sec. IV-C)
  double nullSigmaScale = 100.0;  ///< mm-nh: the null hypothesis's standard deviations over the detection's
  int emWindow = 10;              ///< gpda: steps whose detections each E-step re-weights
  int emIterations = 2;           ///< gpda: E/M rounds per step (and 10 more over every detection at the end)
  double minimumGpdaWeight = 1e-4;///< gpda: weights are clamped below at this
  bool warmStart = true;          ///< mm, mm-nh: solve each step first with every detection's most likely
                                  ///< candidate, then switch to the mixtures (docs/max-mixtures.md)
  double warmStartMinimumPosterior = 0.95;  ///< the warm start uses a candidate only when its posterior (against
                                  ///< the other candidates and, with BirthRule::Unassigned, the unassigned
                                  ///< hypothesis) reaches this: an unambiguous one; 0: every detection
  LandmarkLifecycle::Rule provisional;  ///< BirthRule::Unassigned: the M-of-N rule of provisional landmarks
  SmootherFactory smoother;       ///< the back end; empty: the IncrementalSmoother with semanticSlamSmootherParams()
  bool candidatePreselection = true;  ///< test only: false tests every landmark (docs/association-front-end.md §7)
  bool labelSplit = false;        ///< BirthRule::Unassigned: a landmark whose labels say it holds two objects
                                  ///< splits (LandmarkSplit.h); opt-in, measured in docs/association-front-end.md §5d
  bool nullEscape = true;         ///< mm-nh, BirthRule::Unassigned: step 7 above (docs/association-front-end.md §6b)
  /// mm-nh with nullEscape: a landmark with a single detection on null is tried too when the landmark had a
  /// detection off null at most this many seconds before it (a re-sighting of a tracked object, not a loop
  /// closure); 0: never, two or more on null as in §6b (docs/association-front-end.md §6c; opt-in)
  double nullEscapeWindow = 0.0;
  double anchoringInformation = 2.0;  ///< §10: a pairing anchors when ½ ln det(S R⁻¹) exceeds this (nats), a
                                      ///< merge when SemanticSlam::mergeInformation does
  /// §10: branch B of a split keeps apart the step's anchoring merges too (SemanticSlam::keepMergesApart), so that
  /// it closes no loop by a provisional landmark's merge either; false: only its anchoring pairings, as before.
  bool loopClosureApartKeepsMerges = true;
  /// BirthRule::Unassigned: how the step's joint assignment scores an association (§4). Unset: Joint where a step
  /// assignment is scored (BirthRule::Unassigned and a strategy that decides, not known), Independent elsewhere,
  /// where nothing reads it (resolvedAssignmentScore). Set to Joint, it needs such options.
  std::optional<AssignmentScore> assignmentScore;
  /// §10 (LoopClosureBranches.h): steps a second branch is kept open after an anchoring step before the better one
  /// is kept; 0: no branches. Unset: LoopClosureBranches::kDefaultWindow where branches apply (BirthRule::Unassigned
  /// with ml, mm or mm-nh), none elsewhere.
  std::optional<int> loopClosureBranchWindow;
  /// §10: a third branch at each split, in which the anchoring detections take their next-best landmarks
  /// (SemanticSlam::pairElsewhere). Unset: on for mm-nh wherever it has branches, off elsewhere
  /// (LoopClosureBranches::nextBest).
  std::optional<bool> loopClosureNextBest;
  /// §10: how many loop-closure splits may be open at a time: above 1, a branch of an open split may split again
  /// (LoopClosureBranches.h); 1: one split at a time, an anchoring step during an open split decided as without
  /// branches. Unset: LoopClosureBranches::kDefaultOpenSplits where branches apply, 1 elsewhere.
  std::optional<int> loopClosureOpenSplits;
  /// Decisions on the true history (docs/association-front-end.md §8b): the graph holds the true associations, as
  /// `known`'s does (a landmark per true object, clutter on none), and at every step the strategy's front end decides
  /// the step's detections against that state (steps 1-2 under BirthRule::Unassigned: candidates, the joint gate,
  /// the unassigned hypothesis, the joint assignment). Each decision is recorded (DetectionRecord::decided) and
  /// never applied, so every decision is taken on a history with no error in it. Needs BirthRule::Unassigned and a
  /// strategy other than known; no branches, lifecycle or null escape (nothing the front end decides is applied).
  bool decideOnTrueHistory = false;
};

/// The assignment score a run with these options uses: SemanticSlamOptions::assignmentScore where set; unset, Joint
/// where a step assignment is scored (BirthRule::Unassigned with a strategy that decides), Independent elsewhere.
AssignmentScore resolvedAssignmentScore(const SemanticSlamOptions& options);

/// What became of one detection.
struct DetectionRecord {
  int step = 0;
  int detection = 0;
  Detection measurement;
  std::optional<int> truth;
  std::vector<int> candidates;    ///< gated landmark indices (empty: started a landmark, or `known`)
  std::vector<double> weights;    ///< their normalised association probabilities
  std::optional<int> createdLandmark;
  std::optional<int> knownLandmark;     ///< `known`: the landmark of its truth id (none for clutter)
  std::vector<FactorIndex> factors;     ///< the smoother's factors this detection added
  FactorPtr mixture;                    ///< mm, mm-nh: the max-mixture factor
  Vector semanticLikelihoods;           ///< (P(z_sem | c))_c
  std::vector<double> logLikelihoods;   ///< BirthRule::Unassigned: ln p(z | candidate), geometric × semantic
  double unassignedLogLikelihood = 0.0; ///< BirthRule::Unassigned: ln p(z | unassigned)
  std::optional<int> assigned;          ///< BirthRule::Unassigned: the joint assignment's landmark (none: new)
  bool rejected = false;                ///< the provisional landmark it started was dropped: it is on no landmark
  /// SemanticSlamOptions::decideOnTrueHistory: what the front end decided (the joint assignment's landmark;
  /// nullopt: unassigned) and the landmark the true history had for the detection's object then (nullopt: clutter,
  /// or an object not mapped before this step: unassigned is the right decision).
  std::optional<int> decided;
  std::optional<int> rightDecision;

  /// Whether no factor of the graph holds the detection: the provisional landmark it started was dropped (§5), or
  /// it has no landmark to be on (`known`'s clutter; a detection whose every candidate was taken away). Not a
  /// detection on a mixture's null component, which a factor holds.
  bool onNoFactor() const { return rejected || (candidates.empty() && !createdLandmark && !knownLandmark); }
};

class SemanticSlam {
 public:
  SemanticSlam(const LogHeader& header, SemanticSlamOptions options);
  SemanticSlam(SemanticSlam&&) = default;
  SemanticSlam& operator=(SemanticSlam&&) = default;
  SemanticSlam& operator=(const SemanticSlam&) = delete;  // copies are made by fork() only

  /// An independent copy of the whole run so far: the smoother forked (Smoother::fork, the immutable factors
  /// shared), every other part copied. The fork and this object then evolve independently, and each, fed the same
  /// further steps, gives bit for bit what a single run over all of them gives: a what-if branch of the run
  /// (docs/association-front-end.md §10, two branches at an ambiguous loop closure).
  std::unique_ptr<SemanticSlam> fork() const;

  /// Processes the next step of the log (steps must come in order, the first without odometry): beginStep, then
  /// completeStep.
  void addStep(const TimeStep& step);
  /// The first half of addStep: steps 1-2, up to the joint assignment (BirthRule::Unassigned), found but not yet
  /// applied. Between the halves the run may be forked and the fork told to keepApart() some of the assignment
  /// (docs/association-front-end.md §10). Throws std::logic_error while a begun step is not completed.
  void beginStep(const TimeStep& step);
  /// The rest of the begun step (steps 3-7). Throws std::logic_error without a begun step.
  void completeStep();
  /// (§10) The begun step's records whose joint assignment *anchors*: pairs them with a landmark whose prediction
  /// is uncertain beyond the sensor's own noise, I = ½ ln det(S R⁻¹) > options.anchoringInformation (S the
  /// innovation covariance of step 2, R the detection's). Ascending record indices.
  std::vector<std::size_t> anchoringDetections() const;
  /// (§10) The begun step's `records` start provisional landmarks instead of taking the landmarks the joint
  /// assignment gave them: objects not mapped before, so each such landmark is never merged (§5) with a landmark
  /// active before the step (not only the one it was given: under the uncertainty that made the pairing anchor, the
  /// merge test would otherwise pair it with the next look-alike in reach).
  void keepApart(const std::vector<std::size_t>& records);
  /// (§10, branch B) Nor may the begun step close a loop by a merge: where the merge test (§5) would put a
  /// provisional landmark into a landmark active before the step and the merge is anchoring, mergeInformation above
  /// options.anchoringInformation, the merge is refused and the provisional landmark is kept apart from every landmark
  /// active before the step, as keepApart's are. With keepApart, the begun step closes no loop by a pairing or by a
  /// provisional landmark's merge (a confirmed duplicate's merge, §5c, is not refused).
  void keepMergesApart();
  /// (§10, the third branch) The begun step's `records` may not take the landmarks the joint assignment gave them:
  /// each loses that landmark from its candidates, and the step's joint assignment is found again, so a record
  /// takes its next-best landmark (or starts one, where the unassigned hypothesis is next). Returns whether some
  /// record of `records` now has a landmark: otherwise this branch is keepApart's without its distinctness, and
  /// not worth keeping.
  bool pairElsewhere(const std::vector<std::size_t>& records);

  const Smoother& smoother() const { return *smoother_; }
  /// AssignmentScore::Joint: the joint assignments (this run's and its branches' before it forked) whose search
  /// stopped at its budget (kDefaultJointEvaluations) and kept the best assignment it had found.
  int jointSearchesStopped() const { return jointSearchesStopped_; }
  int steps() const { return static_cast<int>(poseKeys_.size()); }
  /// Landmark variables ever created (dropped and merged ones included: indices are never reused).
  int landmarks() const { return static_cast<int>(landmarks_.size()); }
  const LandmarkLifecycle& lifecycle() const { return lifecycle_; }
  const std::vector<DetectionRecord>& detections() const { return records_; }

  /// Ends the run: gpda's final EM over every detection. Call once, after the last step.
  void finish();

  /// The final estimate as evaluateRun wants it (timeSeconds left for the caller).
  RunResult result(bool withPoseCovariances = true) const;
  /// The landmark (or null hypothesis: nullopt) record r uses at the current estimate, and its weight.
  std::pair<std::optional<int>, double> chosenAssociation(const DetectionRecord& record) const;
  /// The same at `estimate` (which holds the run's variables).
  std::pair<std::optional<int>, double> chosenAssociation(const DetectionRecord& record, const Values& estimate) const;
  /// The smoother factors that only hold a landmark variable in place: the weak priors of provisional and of
  /// merged-away or dropped landmarks (§5), placeholders of the birth density rather than terms of the model.
  std::vector<FactorIndex> weakPriors() const;
  /// Posed landmarks seen by a position-only sensor: each landmark's orientation prior (step 2) is a Gaussian on
  /// its position too, σ = 1e6 m per axis; this returns −2 ln of that position density's peak, d ln(2π σ²), the
  /// term a branch's evidence replaces by the birth density (BranchScore.h). nullopt for other logs.
  std::optional<double> orientationPriorPositionScore() const;
  const UnassignedHypothesis& unassignedHypothesis() const { return unassigned_; }
  const SemanticSlamOptions& options() const { return options_; }
  /// Whether the graph holds the true associations (`known`, or decideOnTrueHistory): clutter is then on no factor.
  bool graphFollowsTruth() const;
  /// rᵀ R⁻¹ r of the detection against the landmark chosenAssociation() gives, at the current estimate (R: the
  /// detection's covariance); nullopt when it is on no landmark.
  std::optional<double> residualChi2(const DetectionRecord& record) const;

 private:
  struct Landmark {
    Key key;
    ClassBelief classBelief;
    std::vector<std::size_t> records;       // records that start it or hold it as a candidate
    std::optional<FactorIndex> weakPrior;   // a provisional landmark's prior, while it has one
    std::vector<int> distinctFrom;          // landmarks split from it or it from them (§5d): never merged with it
  };

  /// The index (into record.candidates) of the candidate the detection's plain factor and warm start use: the
  /// joint assignment's landmark where there is one, else the most likely candidate.
  static int bestCandidate(const DetectionRecord& record);
  void addFirstPose(FactorGraph& factors, Values& values);
  /// A landmark at `value`: provisional (born at `birthTime`) or, without a birth time, confirmed.
  int addLandmark(const Value& value, std::optional<int> truthId, Values& values,
                  std::optional<double> birthTime = std::nullopt);
  /// A prior at `value` with σ = positionSigma per position axis and π per rotation axis: a provisional
  /// landmark's weak prior (§5: positionSigma = r_max), or, with kUnconstrainedSigma, the prior that holds the
  /// orientation of a posed landmark seen by a position-only sensor (nothing else observes it).
  FactorPtr landmarkPrior(int landmark, const Value& value, double positionSigma) const;
  /// The position σ of a provisional (or merged-away) landmark's weak prior: r_max (§5), at least 1 mm.
  double weakPriorSigma() const { return std::max(unassigned_.maxRange(), 1e-3); }
  /// Posterior of the best candidate against the others and (BirthRule::Unassigned) the unassigned hypothesis.
  static double bestPosterior(const DetectionRecord& record);
  /// p_geo(z | landmark) of step 2 at the current estimate: the detection's factor to `landmark` from the newest
  /// pose, linearised under the pair's block of `marginal` (MarginalLikelihood.h). Both birth rules use it. `noise`:
  /// the detection's (MeasurementFactory::detectionNoise), made once for all the landmarks it is weighed against.
  LinearizedLikelihood geometricLikelihood(const JointMarginal& marginal, const Landmark& landmark,
                                           const Detection& detection, const SharedNoiseModel& noise) const;
  /// Candidates among `considered` (ascending landmark indices, all in `marginal`) and their normalised weights for
  /// `detection` at the current estimate (step 2). Landmarks created during this step are not considered (the
  /// marginal predates them; a landmark produces at most one detection per step).
  void findCandidates(const JointMarginal& marginal, const std::vector<int>& considered, DetectionRecord& record) const;
  /// BirthRule::Unassigned: candidates under the joint gate with their likelihoods and the unassigned hypothesis's
  /// (docs/association-front-end.md, §1-3).
  void findCandidatesWithUnassigned(const JointMarginal* marginal, const std::vector<int>& considered,
                                    DetectionRecord& record) const;
  /// Whether the step's detections are assigned jointly (§1-4): BirthRule::Unassigned, not `known`, and the
  /// assignment applied (not decideOnTrueHistory).
  bool jointlyAssigned() const;
  /// decideOnTrueHistory: the front end's decisions on the begun step (steps 1-2, from `first`), recorded with the
  /// right one beside each, not applied.
  void recordDecisions(std::size_t first, const std::vector<int>& decided);
  /// BirthRule::Unassigned: the landmark each of the step's records (from `first`) is assigned, jointly, one
  /// detection per landmark (§4); −1: unassigned. Under AssignmentScore::Joint, jointlyCompatibleAssignment seeded
  /// with the independent one.
  std::vector<int> jointAssignment(std::size_t first) const;
  /// P₀(s), the record's label's predictive under the uniform class prior (§1, §3; 1 without semantics).
  static double labelPrior(const DetectionRecord& record);
  /// (§4) The maximum of the product of each record's own likelihood (Hungarian).
  std::vector<int> independentAssignment(std::size_t first) const;
  /// The assignment applied: the records' assigned landmarks and, by exclusion, their remaining candidates.
  void applyJointAssignment(std::size_t first, const std::vector<int>& assignedLandmark);
  /// The factors of one detection with candidates under the strategy (step 3).
  std::vector<FactorPtr> associationFactors(DetectionRecord& record) const;
  /// The factors a record stands for now: its own landmark's factor, its candidates' factors, or none.
  std::vector<FactorPtr> recordFactors(DetectionRecord& record) const;
  /// Replaces the factors of `touched` records by recordFactors(), removes `removed` and gives each landmark of
  /// `heldByPrior` a weak prior at its estimate (or its value in `newLandmarks`), in one update that also inserts
  /// the variables of `newLandmarks` (with an unobservable orientation: each with its orientation prior).
  void applyEdits(std::vector<std::size_t> touched, std::vector<FactorIndex> removed,
                  const std::vector<int>& heldByPrior = {}, const Values& newLandmarks = Values());
  /// Step 6 (§5) after step `k`'s solve: confirmations, drops of landmarks in the field, merges; one update.
  void updateLifecycle(int k, int landmarksBeforeStep, bool mergesKeptApart);
  void dropLandmark(int landmark, std::vector<std::size_t>& touched);
  void mergeLandmark(int landmark, int into, std::vector<std::size_t>& touched, std::vector<FactorIndex>& removed);
  /// Merge tests (§5, §5c) of every provisional landmark and every confirmed one `seen` at this step against the
  /// active landmarks within the sensor's range of it; confirmed landmarks merged away go to `heldByPrior`. With
  /// `mergesKeptApart` (keepMergesApart), an anchoring merge into one of the `landmarksBeforeStep` is refused.
  void mergeDuplicateLandmarks(const std::vector<bool>& seen, int landmarksBeforeStep, bool mergesKeptApart,
                               std::vector<std::size_t>& touched, std::vector<FactorIndex>& removed,
                               std::vector<int>& heldByPrior);
  /// (§10) How much merging provisional landmark `p` into another tells about the state, the merge test's analogue
  /// of a pairing's I = ½ ln det(S R⁻¹): I = ½ ln det(Σ_d (2 R_w)⁻¹), with `halfLogDetDifference` = ½ ln det Σ_d (the
  /// covariance of the two positions' difference, §5) and R_w = J R Jᵀ the world-position covariance of p's last
  /// detection (UnassignedHypothesis::logBackProjectionJacobian). About 0 when the two positions are known relative
  /// to each other as well as two detections fix them; several nats when they were mapped far apart in time.
  double mergeInformation(int p, double halfLogDetDifference) const;
  /// (§10) `landmark` is an object not mapped before the step: never merged with a landmark active before it.
  void keepApartFromMapped(int landmark, int landmarksBeforeStep);
  /// (§5d) Every active landmark `seen` at this step whose detections' labels say it holds two objects splits: the
  /// detections of the second move to a new landmark at their own position (LandmarkSplit.h); one update.
  void splitLandmarks(const std::vector<bool>& seen);
  /// The class belief of `landmark` rebuilt from the records on it, as step 5 builds it.
  void rebuildClassBelief(int landmark);
  /// Whether record `r`, a sighting of provisional `landmark`, confirms it (§5: spacing in time, viewpoint).
  bool countSighting(int landmark, std::size_t r);
  /// Record `r`, on `landmark`, counts towards confirming it; once confirmed, its weak prior goes.
  void confirmIfDue(int landmark, std::size_t r, std::vector<FactorIndex>& removed);
  /// The position of the robot at `step` (from `newValues` where the pose is not in the smoother yet).
  Vector robotPosition(int step, const Values& newValues = Values()) const;
  /// Removes `landmark` from the record's candidates (weight, likelihood, assignment), renormalising the rest.
  /// Returns false when it was not a candidate.
  static bool removeCandidate(DetectionRecord& record, int landmark);
  /// Steps at which a detection was put on `landmark` (started it, assigned to it, or known to be it).
  std::vector<int> stepsOn(int landmark) const;
  /// The records put on `landmark` (as stepsOn), in step order.
  std::vector<std::size_t> recordsOn(int landmark) const;
  /// (§4) Records [first, end): where two mixtures of one step use one landmark at the estimate, all but the best
  /// lose that candidate; one update. Returns whether anything changed.
  bool repairExclusion(std::size_t first, std::size_t end);
  /// Step 7 of the class comment, for the landmarks seen at step k. Returns whether the smoother was replaced.
  bool escapeNullBasins(int k);
  /// Two converged costs of the escape (chi2, units of −2 ln) closer than this are the same optimum reached twice:
  /// Gauss-Newton's 1e-10 relative stop leaves each within ~1e-10 · chi2 of it (chi2 runs to 1e4-1e5 on the real
  /// logs, the ties seen are within 3e-11), while a different optimum differs by units (§6b).
  static constexpr double kEscapeTolerance = 1e-3;
  /// The records on `landmark` that the front end assigned to it and whose mixture is on its null component.
  std::vector<std::size_t> assignedRecordsOnNull(int landmark) const;
  /// Whether record r's mixture is in force and on its null component at the estimate: the last choice
  /// (nullChecks_) while within its reach, else chosen anew. `seen`, where given, is a landmark's key and its value
  /// in the estimate, looked up once for all its records.
  bool onNullComponent(std::size_t r, const MixtureChoiceCache::KnownValue* seen = nullptr) const;
  /// §6c: the time of the newest step before record `lone`'s at which a detection was on `landmark` and off null.
  std::optional<double> lastSightingOffNull(int landmark, std::size_t lone) const;
  FactorPtr gpdaFactor(const DetectionRecord& record, int landmark, double weight) const;
  /// E-step for one gpda record at the current estimate; returns whether any factor changed.
  bool reweight(DetectionRecord& record);
  void expectationMaximization(std::size_t firstRecord, int iterations);

  LogHeader header_;
  SemanticSlamOptions options_;
  MeasurementFactory factory_;
  AssociationGate gate_;
  UnassignedHypothesis unassigned_;
  LandmarkLifecycle lifecycle_;
  bool orientationUnobservable_;  // posed landmarks, position-only sensor: every new landmark gets an orientation prior
  CandidatePreselection preselection_;  // §7 of docs/association-front-end.md
  /// Owns the smoother; a copy is a fork (Smoother::fork: the immutable factors shared), so that SemanticSlam's
  /// own copy, which only fork() makes, is member by member.
  class ForkingSmoother {
   public:
    explicit ForkingSmoother(std::unique_ptr<Smoother> smoother) : smoother_(std::move(smoother)) {}
    ForkingSmoother(const ForkingSmoother& other) : smoother_(other.smoother_->fork()) {}
    ForkingSmoother(ForkingSmoother&&) = default;
    ForkingSmoother& operator=(ForkingSmoother&&) = default;
    ForkingSmoother& operator=(const ForkingSmoother&) = delete;
    /// Replaces the smoother (the null escape's accepted trial).
    ForkingSmoother& operator=(std::unique_ptr<Smoother> smoother) {
      smoother_ = std::move(smoother);
      return *this;
    }
    Smoother* operator->() const { return smoother_.get(); }
    Smoother& operator*() const { return *smoother_; }

   private:
    std::unique_ptr<Smoother> smoother_;
  };
  ForkingSmoother smoother_;
  std::vector<std::size_t> nullsTried_;  // per landmark: its detections on null when step 7 last failed for it
  std::vector<Key> poseKeys_;
  std::vector<Landmark> landmarks_;
  std::map<int, int> landmarkOfTruthId_;  // `known` and map priors: the log's landmark id → landmark index
  std::vector<DetectionRecord> records_;
  std::vector<std::size_t> firstRecordOfStep_;
  std::vector<double> stepTimes_;
  /// Per record: onNullComponent's last choice and its reach (§6b).
  mutable MixtureChoiceCache nullChecks_;
  mutable int jointSearchesStopped_ = 0;  // jointAssignment's, for jointSearchesStopped()
  /// A step between beginStep and completeStep.
  struct PendingStep {
    double time = 0.0;
    FactorGraph propagation;  // the propagation, where it shares the association's solve (else empty)
    Values newValues;
    std::optional<JointMarginal> marginal;  // of the propagated pose and the `considered` landmarks (step 2)
    std::vector<int> considered;
    std::size_t first = 0;                  // the step's first record
    int landmarksBeforeStep = 0;
    std::vector<int> assignedLandmark;      // jointAssignment() of the step's records
    std::vector<std::size_t> keptApart;     // keepApart()'s records
    bool mergesKeptApart = false;           // keepMergesApart()
  };
  std::optional<PendingStep> pending_;

  SemanticSlam(const SemanticSlam& other) = default;  // for fork(): every member copied, the smoother forked
};

}  // namespace semslam
