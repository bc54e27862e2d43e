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
//      and l is a candidate when its innovation chi2 passes the gate (AssociationGate.h). A candidate's weight is
//          w_l ∝ p_geo(z | l) · Σ_c P(z_sem | c) P(c | l)            (ClassBelief.h)
//      normalised over the candidates. No candidate: z starts a new landmark at its back-projection from x̄_k;
//      with BirthRule::Unassigned (docs/association-front-end.md) the gate is the joint geometric × semantic one,
//      every detection also has the unassigned hypothesis (UnassignedHypothesis.h), and the step's detections are
//      assigned jointly, at most one per landmark (Hungarian); an unassigned detection starts a new landmark;
//   3. the strategy's factors (AssociationStrategy.h): mm builds a MaxMixtureFactor with components w_l; mm-nh adds
//      the null hypothesis, the detection's factor to the most likely candidate (with BirthRule::Unassigned: the
//      jointly assigned landmark, which the warm start below uses too) with standard deviations scaled by
//      nullSigmaScale, with weight nullWeight (the candidates share 1 − nullWeight); gpda adds one factor per
//      candidate whose information is scaled by w_l;
//   4. the smoother re-solves (mm, mm-nh with warmStart: first with each detection's most likely candidate, then
//      again with the mixtures, so that they choose their components near the step's solution rather than at the
//      odometry prediction, where the null hypothesis would win every detection once the odometry is poor); gpda runs emIterations E-steps over the detections of the last emWindow steps
//      (weights recomputed at the current estimate, Σ_joint = 0, i.e. N(z; h(X̂), R) times the semantic term, the
//      same likelihood code with no state uncertainty) and M-steps (factors replaced, re-solve);
//   5. class beliefs: each candidate's P(c | l) is updated with the detection's class likelihoods, tempered by its
//      association weight (ClassBelief.h).
// Decisions where paper B is silent are in docs/max-mixtures.md.
//
// Invariants: landmark indices are dense, 0-based, in creation order, and are the landmark ids of every output;
// every detection of every step processed has exactly one DetectionRecord.

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/ClassBelief.h"
#include "semslam/association/MeasurementFactory.h"
#include "semslam/association/UnassignedHypothesis.h"
#include "semslam/models/RunResult.h"
#include "semslam/slam/AssociationStrategy.h"
#include "semslam/solve/SmootherFactory.h"

namespace semslam {

/// How a detection that matches no mapped landmark starts one (docs/association-front-end.md).
enum class BirthRule {
  Threshold,   ///< paper B: a landmark starts when no landmark passes the geometric gate
  Unassigned,  ///< every detection also has the unassigned hypothesis (UnassignedHypothesis.h); the step's
               ///< detections are assigned jointly, one per landmark (Hungarian), under the joint gate
};

/// "threshold" | "unassigned"; anything else throws std::invalid_argument.
BirthRule parseBirthRule(const std::string& name);
std::string birthRuleName(BirthRule rule);

struct SemanticSlamOptions {
  AssociationStrategy strategy = AssociationStrategy::MaxMixtureNullHypothesis;
  BirthRule birth = BirthRule::Threshold;
  double unassignedRate = UnassignedHypothesis::kDefaultRate;  ///< μ: unassigned detections expected per step
  double gateConfidence = AssociationGate::kDefaultConfidence;
  double nullWeight = 0.1;        ///< mm-nh: weight of the null hypothesis (B, sec. IV-C)
  double nullSigmaScale = 100.0;  ///< mm-nh: the null hypothesis's standard deviations over the detection's
  int emWindow = 10;              ///< gpda: steps whose detections each E-step re-weights
  int emIterations = 2;           ///< gpda: E/M rounds per step (and 10 more over every detection at the end)
  double minimumGpdaWeight = 1e-4;///< gpda: weights are clamped below at this
  bool warmStart = true;          ///< mm, mm-nh: solve each step first with every detection's most likely
                                  ///< candidate, then switch to the mixtures (docs/max-mixtures.md)
  SmootherFactory smoother;       ///< the back end; empty: the IncrementalSmoother
};

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
};

class SemanticSlam {
 public:
  SemanticSlam(const LogHeader& header, SemanticSlamOptions options);

  /// Processes the next step of the log (steps must come in order, the first without odometry).
  void addStep(const TimeStep& step);

  const Smoother& smoother() const { return *smoother_; }
  int steps() const { return static_cast<int>(poseKeys_.size()); }
  int landmarks() const { return static_cast<int>(landmarks_.size()); }
  const std::vector<DetectionRecord>& detections() const { return records_; }

  /// Ends the run: gpda's final EM over every detection. Call once, after the last step.
  void finish();

  /// The final estimate as evaluateRun wants it (timeSeconds left for the caller).
  RunResult result(bool withPoseCovariances = true) const;
  /// The landmark (or null hypothesis: nullopt) record r uses at the current estimate, and its weight.
  std::pair<std::optional<int>, double> chosenAssociation(const DetectionRecord& record) const;

 private:
  struct Landmark {
    Key key;
    ClassBelief classBelief;
  };

  /// The index (into record.candidates) of the candidate the detection's plain factor and warm start use: the
  /// joint assignment's landmark where there is one, else the most likely candidate.
  static int bestCandidate(const DetectionRecord& record);
  void addFirstPose(FactorGraph& factors, Values& values);
  int addLandmark(const Value& value, std::optional<int> truthId, Values& values);
  /// p_geo(z | landmark) of step 2 at the current estimate: the detection's factor to `landmark` from the newest
  /// pose, linearised under the pair's block of `marginal` (MarginalLikelihood.h). Both birth rules use it.
  LinearizedLikelihood geometricLikelihood(const JointMarginal& marginal, const Landmark& landmark,
                                           const Detection& detection) const;
  /// Candidates and their normalised weights for `detection` at the current estimate (step 2).
  /// Landmarks created during this step are not candidates (the marginal predates them; a landmark produces at
  /// most one detection per step).
  void findCandidates(const JointMarginal& marginal, int landmarkCount, DetectionRecord& record) const;
  /// BirthRule::Unassigned: candidates under the joint gate with their likelihoods and the unassigned hypothesis's
  /// (docs/association-front-end.md, §1-3).
  void findCandidatesWithUnassigned(const JointMarginal* marginal, int landmarkCount, DetectionRecord& record) const;
  /// BirthRule::Unassigned: the step's records (from `first`) assigned jointly, one detection per landmark (§4).
  void assignJointly(std::size_t first);
  /// The factors of one detection with candidates under the strategy (step 3).
  std::vector<FactorPtr> associationFactors(DetectionRecord& record) const;
  FactorPtr gpdaFactor(const DetectionRecord& record, int landmark, double weight) const;
  /// E-step for one gpda record at the current estimate; returns whether any factor changed.
  bool reweight(DetectionRecord& record);
  void expectationMaximization(std::size_t firstRecord, int iterations);

  LogHeader header_;
  SemanticSlamOptions options_;
  MeasurementFactory factory_;
  AssociationGate gate_;
  UnassignedHypothesis unassigned_;
  std::unique_ptr<Smoother> smoother_;
  std::vector<Key> poseKeys_;
  std::vector<Landmark> landmarks_;
  std::map<int, int> landmarkOfTruthId_;  // `known` and map priors: the log's landmark id → landmark index
  std::vector<DetectionRecord> records_;
  std::vector<std::size_t> firstRecordOfStep_;
};

}  // namespace semslam
