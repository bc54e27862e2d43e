#include "semslam/slam/SemanticSlam.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "semslam/association/JointCompatibility.h"
#include "semslam/association/LandmarkSplit.h"
#include "semslam/association/MarginalLikelihood.h"
#include "semslam/factors/MaxMixtureFactor.h"
#include "semslam/models/HypothesisComponent.h"
#include "semslam/models/ValueConversions.h"
#include "semslam/slam/SemanticSlamSmoother.h"
#include "semslam/solve/HungarianAssignment.h"
#include "semslam/solve/Optimizer.h"

namespace semslam {
namespace {

constexpr double kGaugeSigma = 1e-6;
/// Position σ of a prior that holds only a landmark's orientation: information 1e-12 per m², nothing beside any
/// detection, yet a proper Gaussian.
constexpr double kUnconstrainedSigma = 1e6;
/// Scale of the warm start's Cauchy kernel, in standard deviations of the detection.
constexpr double kWarmStartCauchyScale = 3.0;

/// Normalises log-weights into probabilities (log-sum-exp); all −∞ gives the uniform distribution.
std::vector<double> normalizeLogWeights(const std::vector<double>& logWeights) {
  const double maximum = *std::max_element(logWeights.begin(), logWeights.end());
  std::vector<double> weights;
  double sum = 0.0;
  for (double w : logWeights) {
    weights.push_back(std::isfinite(maximum) ? std::exp(w - maximum) : 1.0);
    sum += weights.back();
  }
  for (double& w : weights) w /= sum;
  return weights;
}

int argmax(const std::vector<double>& values) {
  return static_cast<int>(std::max_element(values.begin(), values.end()) - values.begin());
}

/// Weight of a forbidden pair in the joint assignment: below the smallest allowed weight by more than the sum of
/// all their magnitudes, so no assignment that uses one can be optimal (every row keeps its own unassigned
/// column), yet finite (the Hungarian solver takes finite weights only) and no larger in magnitude than needed
/// (the solver's tie tolerance scales with the largest |weight|).
double forbiddenWeight(const std::vector<double>& allowed) {
  double spread = 1.0, smallest = 0.0;
  for (double w : allowed) {
    spread += std::abs(w);
    smallest = std::min(smallest, w);
  }
  return smallest - spread;
}

}  // namespace

BirthRule parseBirthRule(const std::string& name) {
  if (name == "threshold") return BirthRule::Threshold;
  if (name == "unassigned") return BirthRule::Unassigned;
  throw std::invalid_argument("unknown birth rule \"" + name + "\" (threshold, unassigned)");
}

std::string birthRuleName(BirthRule rule) { return rule == BirthRule::Threshold ? "threshold" : "unassigned"; }

AssignmentScore parseAssignmentScore(const std::string& name) {
  if (name == "independent") return AssignmentScore::Independent;
  if (name == "joint") return AssignmentScore::Joint;
  throw std::invalid_argument("unknown assignment score \"" + name + "\" (independent, joint)");
}

std::string assignmentScoreName(AssignmentScore score) {
  return score == AssignmentScore::Independent ? "independent" : "joint";
}

AssignmentScore resolvedAssignmentScore(const SemanticSlamOptions& options) {
  if (options.assignmentScore) return *options.assignmentScore;
  const bool scored = options.birth == BirthRule::Unassigned && options.strategy != AssociationStrategy::Known;
  return scored ? AssignmentScore::Joint : AssignmentScore::Independent;  // (§4, "The default")
}

int SemanticSlam::bestCandidate(const DetectionRecord& record) {
  if (record.assigned) {
    const auto found = std::find(record.candidates.begin(), record.candidates.end(), *record.assigned);
    if (found != record.candidates.end()) return static_cast<int>(found - record.candidates.begin());
  }
  return argmax(record.weights);
}

SemanticSlam::SemanticSlam(const LogHeader& header, SemanticSlamOptions options)
    : header_(header),
      options_(std::move(options)),
      factory_(header),
      gate_(options_.gateConfidence),
      unassigned_(header, options_.unassignedRate, options_.unassignedRateWeight, options_.unassignedRateMemory),
      lifecycle_(options_.provisional),
      orientationUnobservable_(factory_.landmarksHavePose() && header.sensor.kind != SensorKind::RelativePose),
      preselection_(header, gate_),
      smoother_(options_.smoother ? options_.smoother()
                                   : smootherFactory(SmootherKind::Incremental, {}, semanticSlamSmootherParams())()) {
  if (!(options_.nullWeight > 0.0 && options_.nullWeight < 1.0)) {
    throw std::invalid_argument("null-hypothesis weight must be in (0, 1)");
  }
  if (!(options_.nullSigmaScale >= 1.0)) throw std::invalid_argument("null-hypothesis sigma scale must be >= 1");
  if (options_.emWindow < 1 || options_.emIterations < 0) throw std::invalid_argument("bad EM window or iterations");
  if (!(options_.nullEscapeWindow >= 0.0 && std::isfinite(options_.nullEscapeWindow))) {
    throw std::invalid_argument("null escape window must be a finite number of seconds >= 0");
  }
  if (options_.decideOnTrueHistory &&
      (options_.strategy == AssociationStrategy::Known || options_.birth != BirthRule::Unassigned)) {
    throw std::invalid_argument("decisions on the true history need a strategy that decides (not known) and the "
                                "unassigned birth rule, whose joint assignment is the decision");
  }
  if (options_.assignmentScore == AssignmentScore::Joint &&
      (options_.strategy == AssociationStrategy::Known || options_.birth != BirthRule::Unassigned)) {
    throw std::invalid_argument("the joint assignment score needs a strategy that decides (not known) and the "
                                "unassigned birth rule, whose step assignment it scores");
  }
}

int SemanticSlam::addLandmark(const Value& value, std::optional<int> truthId, Values& values,
                              std::optional<double> birthTime) {
  const int index = landmarks();
  const Key key = landmarkKey(static_cast<std::uint64_t>(index));
  landmarks_.push_back({key, ClassBelief(header_.classes), {}, std::nullopt, {}});
  if (birthTime) {
    lifecycle_.addProvisional(*birthTime, robotPosition(steps() - 1, values));
  } else {
    lifecycle_.addConfirmed();
  }
  if (truthId) landmarkOfTruthId_.emplace(*truthId, index);
  values.insert(key, value);
  return index;
}

void SemanticSlam::addFirstPose(FactorGraph& factors, Values& values) {
  const Key pose = poseKey(0);
  values.insert(pose, factory_.initialPose(header_));
  if (header_.initialPose) {
    factors.add(factory_.posePriorFactor(pose, *header_.initialPose));
  } else {
    PosePrior gauge{toPose(factory_.initialPose(header_)),
                    Matrix::Identity(factory_.poseTangentDimension(), factory_.poseTangentDimension()) *
                        (kGaugeSigma * kGaugeSigma)};
    factors.add(factory_.posePriorFactor(pose, gauge));
  }
  for (const LandmarkPrior& prior : header_.landmarkPriors) {
    const int index = addLandmark(factory_.landmarkValue(prior.mean), prior.id, values);
    factors.add(factory_.landmarkPriorFactor(landmarks_[index].key, prior));
  }
}

std::unique_ptr<SemanticSlam> SemanticSlam::fork() const {
  return std::unique_ptr<SemanticSlam>(new SemanticSlam(*this));
}

void SemanticSlam::addStep(const TimeStep& step) {
  beginStep(step);
  completeStep();
}

void SemanticSlam::beginStep(const TimeStep& step) {
  if (pending_) throw std::logic_error("beginStep: the previous step was not completed");
  // 1. Propagate.
  const int k = steps();
  const Key pose = poseKey(static_cast<std::uint64_t>(k));
  stepTimes_.push_back(step.time);
  FactorGraph propagation;
  Values newValues;
  if (k == 0) {
    if (step.odometry) throw std::invalid_argument("the first step must not have odometry");
    addFirstPose(propagation, newValues);
  } else {
    if (!step.odometry) throw std::invalid_argument("step " + std::to_string(k) + " has no odometry");
    const Key previous = poseKeys_.back();
    newValues.insert(pose, factory_.predictPose(smoother_->estimate().value(previous), *step.odometry));
    propagation.add(factory_.odometryFactor(previous, pose, *step.odometry));
  }
  poseKeys_.push_back(pose);
  firstRecordOfStep_.push_back(records_.size());
  const bool decides = options_.strategy != AssociationStrategy::Known;  // (decideOnTrueHistory included)
  if (!step.detections.empty() && decides && !landmarks_.empty()) {
    // The candidates' weights need the marginal of the propagated pose: solve before associating. (Otherwise
    // propagation and association share one solve.)
    smoother_->update(propagation, newValues);
    propagation = FactorGraph();
    newValues = Values();
  }

  // 2. Candidates and weights, all against the marginal of the propagated estimate, over the landmarks that can
  // pass the gate (docs/association-front-end.md, §7; every landmark without candidatePreselection). Landmarks
  // created during this step are not among them.
  std::optional<JointMarginal> marginal;
  std::vector<int> considered;
  if (decides && !landmarks_.empty() && !step.detections.empty()) {
    const auto active = [this](int j) { return lifecycle_.active(j); };  // not dropped or merged (§5)
    if (options_.candidatePreselection) {
      considered = preselection_.select(*smoother_, pose, step.detections, options_.birth == BirthRule::Unassigned,
                                        landmarks(), [this](int j) { return landmarks_[j].key; }, active);
    } else {
      for (int j = 0; j < landmarks(); ++j) {
        if (active(j)) considered.push_back(j);
      }
    }
    std::vector<Key> keys = {pose};
    for (int j : considered) keys.push_back(landmarks_[j].key);
    marginal = smoother_->jointMarginal(keys);
    if (options_.candidatePreselection) preselection_.refresh(*marginal, considered);
  }
  PendingStep& pending = pending_.emplace();
  pending.time = step.time;
  pending.propagation = std::move(propagation);
  pending.newValues = std::move(newValues);
  pending.marginal = std::move(marginal);
  pending.considered = std::move(considered);
  pending.landmarksBeforeStep = landmarks();
  pending.first = records_.size();
  for (std::size_t i = 0; i < step.detections.size(); ++i) {
    DetectionRecord record;
    record.step = k;
    record.detection = static_cast<int>(i);
    record.measurement = step.detections[i];
    record.truth = step.detections[i].truthId;
    record.semanticLikelihoods = semanticLikelihoods(header_, step.detections[i]);
    records_.push_back(std::move(record));
  }
  // The sensor field's extents, as the data define them: the unassigned density (§1), also in the branch score.
  for (const Detection& detection : step.detections) unassigned_.observe(detection);
  if (jointlyAssigned() || options_.decideOnTrueHistory) {
    // (docs/association-front-end.md, §1-4): every candidate of the step against the marginal from before it,
    // then one joint assignment with the unassigned hypothesis (applied by completeStep, or only recorded).
    for (std::size_t r = pending.first; r < records_.size(); ++r) {
      findCandidatesWithUnassigned(pending.marginal ? &*pending.marginal : nullptr, pending.considered, records_[r]);
    }
    pending.assignedLandmark = jointAssignment(pending.first);
    if (options_.decideOnTrueHistory) recordDecisions(pending.first, pending.assignedLandmark);
  }
}

void SemanticSlam::recordDecisions(std::size_t first, const std::vector<int>& decided) {
  for (std::size_t r = first; r < records_.size(); ++r) {
    DetectionRecord& record = records_[r];
    const int landmark = decided[r - first];
    if (landmark >= 0) record.decided = landmark;
    if (scoredTruth(record.truth) && *record.truth != kNotALandmark) {
      const auto found = landmarkOfTruthId_.find(*record.truth);
      if (found != landmarkOfTruthId_.end()) record.rightDecision = found->second;
    }
    // The graph takes the true association (completeStep, as `known`): nothing of the decision stays in the record.
    record.candidates.clear();
    record.weights.clear();
    record.logLikelihoods.clear();
  }
}

bool SemanticSlam::jointlyAssigned() const {
  return !graphFollowsTruth() && options_.birth == BirthRule::Unassigned;
}

bool SemanticSlam::graphFollowsTruth() const {
  return options_.strategy == AssociationStrategy::Known || options_.decideOnTrueHistory;
}

void SemanticSlam::completeStep() {
  if (!pending_) throw std::logic_error("completeStep: no step begun");
  const PendingStep pending = std::move(*pending_);
  pending_.reset();
  const int k = steps() - 1;
  const Key pose = poseKeys_.back();
  const bool truthAssociations = graphFollowsTruth();
  const bool jointly = jointlyAssigned();
  const std::optional<JointMarginal>& marginal = pending.marginal;
  const std::vector<int>& considered = pending.considered;
  const std::size_t first = pending.first;
  const int landmarksBeforeStep = pending.landmarksBeforeStep;
  if (jointly) applyJointAssignment(first, pending.assignedLandmark);
  // μ from the run (§10): the step's detections its joint assignment left unassigned, as finally decided (a branch
  // that keeps closures apart counts them; a step without detections counts as a step with none). A run without a
  // joint assignment (threshold births, `known`) counts nothing and keeps μ₀.
  if (jointly || options_.decideOnTrueHistory) {
    unassigned_.countStep(static_cast<int>(
        std::count_if(pending.assignedLandmark.begin(), pending.assignedLandmark.end(), [](int j) { return j < 0; })));
  }
  FactorGraph associations = pending.propagation;
  Values values = pending.newValues;
  std::vector<std::size_t> factorsOfRecord;  // how many of `associations` each of this step's records added
  std::vector<bool> warmStarted;             // whose first factor is the warm start's, to become the mixture
  FactorGraph weakPriors;                    // of the step's provisional landmarks (§5), after every record's
  std::vector<int> weakPriorLandmarks;
  FactorGraph orientationPriors;             // of the step's new landmarks whose orientation is unobservable, last
  for (std::size_t r = first; r < records_.size(); ++r) {
    DetectionRecord& record = records_[r];
    const std::size_t factorsBefore = associations.size();
    const Value& robot = values.exists(pose) ? values.value(pose) : smoother_->estimate().value(pose);

    if (truthAssociations) {
      if (scoredTruth(record.truth) && *record.truth != kNotALandmark) {  // clutter and "unknown": no factor
        const auto found = landmarkOfTruthId_.find(*record.truth);
        int index = 0;
        if (found != landmarkOfTruthId_.end()) {
          index = found->second;
        } else {
          const Value initial = factory_.initialLandmark(record.measurement, robot);
          index = addLandmark(initial, *record.truth, values);
          if (orientationUnobservable_) orientationPriors.add(landmarkPrior(index, initial, kUnconstrainedSigma));
        }
        record.knownLandmark = index;
        associations.add(factory_.detectionFactor(pose, landmarks_[index].key, record.measurement));
        landmarks_[index].classBelief.update(record.semanticLikelihoods);
      }
    } else {
      if (!jointly && marginal) findCandidates(*marginal, considered, record);
      if (record.candidates.empty()) {
        // Under BirthRule::Unassigned the new landmark is provisional, held by a weak prior (§5).
        const std::optional<double> birthTime = jointly ? std::optional<double>(pending.time) : std::nullopt;
        const Value initial = factory_.initialLandmark(record.measurement, robot);
        const int index = addLandmark(initial, std::nullopt, values, birthTime);
        record.createdLandmark = index;
        landmarks_[index].records.push_back(r);
        associations.add(factory_.detectionFactor(pose, landmarks_[index].key, record.measurement));
        landmarks_[index].classBelief.update(record.semanticLikelihoods);
        if (birthTime) {
          weakPriors.add(landmarkPrior(index, initial, weakPriorSigma()));
          weakPriorLandmarks.push_back(index);
        }
        if (orientationUnobservable_) orientationPriors.add(landmarkPrior(index, initial, kUnconstrainedSigma));
      } else {
        const std::vector<FactorPtr> factors = associationFactors(record);
        const bool warm = record.mixture && options_.warmStart &&
                          bestPosterior(record) >= options_.warmStartMinimumPosterior;
        if (warm) {
          // Warm start: this solve uses the (unambiguous) most likely candidate under a Cauchy kernel (an outlier
          // pulls little); the mixture replaces it below.
          const int best = record.candidates[bestCandidate(record)];
          associations.add(factory_.detectionFactor(pose, landmarks_[best].key, record.measurement, 1.0,
                                                    std::make_shared<CauchyKernel>(kWarmStartCauchyScale)));
        } else {
          for (const FactorPtr& factor : factors) associations.add(factor);
        }
        warmStarted.resize(r - first + 1, false);
        warmStarted[r - first] = warm;
        for (std::size_t c = 0; c < record.candidates.size(); ++c) {
          landmarks_[record.candidates[c]].records.push_back(r);
          landmarks_[record.candidates[c]].classBelief.update(record.semanticLikelihoods, record.weights[c]);
        }
      }
    }
    factorsOfRecord.push_back(associations.size() - factorsBefore);
  }
  warmStarted.resize(records_.size() - first, false);
  for (std::size_t r : pending.keptApart) keepApartFromMapped(records_[r].createdLandmark.value(), landmarksBeforeStep);
  for (const FactorPtr& prior : weakPriors) associations.add(prior);
  for (const FactorPtr& prior : orientationPriors) associations.add(prior);

  // 4. Solve, and remember which smoother factors belong to which detection (they follow any propagation ones).
  const std::vector<FactorIndex> indices = smoother_->update(associations, values);
  std::size_t next = pending.propagation.size();
  for (std::size_t i = 0; i < factorsOfRecord.size(); ++i) {
    DetectionRecord& record = records_[firstRecordOfStep_.back() + i];
    for (std::size_t c = 0; c < factorsOfRecord[i]; ++c) record.factors.push_back(indices.at(next++));
  }
  for (int landmark : weakPriorLandmarks) landmarks_[landmark].weakPrior = indices.at(next++);
  bool switched = false;
  for (std::size_t i = 0; i < warmStarted.size(); ++i) {
    if (!warmStarted[i]) continue;
    const DetectionRecord& record = records_[first + i];
    smoother_->replaceFactor(record.factors.at(0), record.mixture);
    switched = true;
  }
  if (switched) smoother_->update();
  if (options_.strategy == AssociationStrategy::Gpda && !graphFollowsTruth() && options_.emIterations > 0) {
    const int firstStep = std::max(0, k + 1 - options_.emWindow);
    expectationMaximization(firstRecordOfStep_[firstStep], options_.emIterations);
  }
  if (jointly) {
    updateLifecycle(k, landmarksBeforeStep, pending.mergesKeptApart);
    while (repairExclusion(first, records_.size())) {
    }
    if (options_.strategy == AssociationStrategy::MaxMixtureNullHypothesis && options_.nullEscape) {
      escapeNullBasins(k);
    }
  }
}

std::vector<std::size_t> SemanticSlam::assignedRecordsOnNull(int landmark) const {
  std::vector<std::size_t> onNull;
  const Key key = landmarks_[landmark].key;
  const MixtureChoiceCache::KnownValue seen = {key, &smoother_->estimate().value(key)};
  for (std::size_t r : recordsOn(landmark)) {
    const DetectionRecord& record = records_[r];
    if (record.assigned == landmark && onNullComponent(r, &seen)) onNull.push_back(r);
  }
  return onNull;
}

bool SemanticSlam::onNullComponent(std::size_t r, const MixtureChoiceCache::KnownValue* seen) const {
  const DetectionRecord& record = records_[r];
  if (!record.mixture || record.factors.size() != 1) return false;  // no mixture in force (a plain factor, or none)
  const int active = nullChecks_.activeComponent(r, record.mixture, smoother_->estimate(), seen);
  return active >= static_cast<int>(record.candidates.size());  // the null component is last
}

std::optional<double> SemanticSlam::lastSightingOffNull(int landmark, std::size_t lone) const {
  const std::vector<std::size_t> on = recordsOn(landmark);  // in step order
  for (auto r = on.rbegin(); r != on.rend(); ++r) {
    const DetectionRecord& record = records_[*r];
    if (record.step >= records_[lone].step) continue;
    if (!onNullComponent(*r)) return stepTimes_[static_cast<std::size_t>(record.step)];
  }
  return std::nullopt;
}

bool SemanticSlam::escapeNullBasins(int k) {
  std::vector<int> seen;
  for (std::size_t r = firstRecordOfStep_[static_cast<std::size_t>(k)]; r < records_.size(); ++r) {
    if (records_[r].assigned && lifecycle_.active(*records_[r].assigned)) seen.push_back(*records_[r].assigned);
  }
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  nullsTried_.resize(static_cast<std::size_t>(landmarks()), 0);
  bool escaped = false;
  std::optional<double> unchangedCost;  // Σ chi2 of the graph in force, converged; after a kept try, the try's
  for (int j : seen) {
    const std::vector<std::size_t> onNull = assignedRecordsOnNull(j);
    std::size_t& tried = nullsTried_[static_cast<std::size_t>(j)];
    if (onNull.empty() || onNull.size() <= tried) continue;  // no news since the last try
    if (onNull.size() == 1) {  // an outlier, unless the landmark was seen off null just before it (§6c)
      if (options_.nullEscapeWindow <= 0.0) continue;
      const std::optional<double> last = lastSightingOffNull(j, onNull[0]);
      const double loneTime = stepTimes_[static_cast<std::size_t>(records_[onNull[0]].step)];
      if (!last || loneTime - *last > options_.nullEscapeWindow) continue;
    }
    tried = onNull.size();
    // The unchanged graph, converged, against the trial: the same factors, the null detections first held on the
    // landmark, then given their mixtures back at the estimate that pulled (step 7 of the class comment).
    if (!unchangedCost) unchangedCost = optimize(smoother_->factors(), smoother_->estimate()).finalChi2;
    std::unique_ptr<Smoother> trial = smoother_->fork();
    for (std::size_t r : onNull) {
      const DetectionRecord& record = records_[r];
      trial->replaceFactor(record.factors[0], factory_.detectionFactor(poseKeys_[static_cast<std::size_t>(record.step)],
                                                                       landmarks_[j].key, record.measurement));
    }
    trial->update();
    trial->converge();
    for (std::size_t r : onNull) trial->replaceFactor(records_[r].factors[0], records_[r].mixture);
    trial->update();
    trial->converge();
    const double trialCost = trial->factors().chi2(trial->estimate());
    if (trialCost <= *unchangedCost + kEscapeTolerance) {  // lower, or the same optimum: kept (§6b)
      smoother_ = std::move(trial);
      unchangedCost = trialCost;
      tried = 0;
      escaped = true;
    }
  }
  return escaped;
}

LinearizedLikelihood SemanticSlam::geometricLikelihood(const JointMarginal& marginal, const Landmark& landmark,
                                                       const Detection& detection,
                                                       const SharedNoiseModel& noise) const {
  const Key pose = poseKeys_.back();
  const std::vector<FactorPtr> factor = {factory_.detectionFactor(pose, landmark.key, detection, noise)};
  return linearizedLikelihood(factor, smoother_->estimate(), marginal.restrictedTo({pose, landmark.key}));
}

void SemanticSlam::findCandidates(const JointMarginal& marginal, const std::vector<int>& considered,
                                  DetectionRecord& record) const {
  std::vector<double> logWeights;
  const SharedNoiseModel noise = factory_.detectionNoise(record.measurement);
  for (int j : considered) {
    const Landmark& landmark = landmarks_[j];
    const LinearizedLikelihood geometric = geometricLikelihood(marginal, landmark, record.measurement, noise);
    if (!gate_.accepts(geometric)) continue;
    const double semantic = landmark.classBelief.predictive(record.semanticLikelihoods);
    if (!(semantic > 0.0)) continue;  // a label this landmark's class belief rules out (exact model, p = 0)
    record.candidates.push_back(j);
    logWeights.push_back(geometric.logLikelihood + std::log(semantic));  // (B, sec. IV-B)
  }
  if (!record.candidates.empty()) record.weights = normalizeLogWeights(logWeights);
}

double SemanticSlam::labelPrior(const DetectionRecord& record) {
  // P₀(s): the label's predictive under the uniform class prior (1 without semantics). A label that every class
  // rules out (all likelihoods 0, e.g. an exact model) carries no usable information: it counts as uninformative
  // here, and every landmark's predictive of it is 0, so the detection is unassigned.
  const double prior = record.semanticLikelihoods.size() > 0 ? record.semanticLikelihoods.mean() : 1.0;
  return prior > 0.0 && std::isfinite(prior) ? prior : 1.0;
}

void SemanticSlam::findCandidatesWithUnassigned(const JointMarginal* marginal, const std::vector<int>& considered,
                                                DetectionRecord& record) const {
  const double labelPrior = SemanticSlam::labelPrior(record);
  record.unassignedLogLikelihood = unassigned_.logDensity(record.measurement) + std::log(labelPrior);  // (§1)
  if (!marginal) return;
  const SharedNoiseModel noise = factory_.detectionNoise(record.measurement);
  for (int j : considered) {
    const Landmark& landmark = landmarks_[j];
    const double semantic = landmark.classBelief.predictive(record.semanticLikelihoods);
    if (!(semantic > 0.0)) continue;  // a label this landmark's class belief rules out
    const LinearizedLikelihood geometric = geometricLikelihood(*marginal, landmark, record.measurement, noise);
    // The joint gate (§3): g = d² − 2 ln(P(s | j) / P₀(s)) against the χ²_m quantile.
    const double jointStatistic = geometric.innovationChi2 - 2.0 * std::log(semantic / labelPrior);
    if (jointStatistic > gate_.threshold(geometric.dimension)) continue;
    record.candidates.push_back(j);
    record.logLikelihoods.push_back(geometric.logLikelihood + std::log(semantic));
  }
  if (!record.candidates.empty()) record.weights = normalizeLogWeights(record.logLikelihoods);
}

std::vector<int> SemanticSlam::jointAssignment(std::size_t first) const {
  const std::vector<int> independent = independentAssignment(first);
  // One detection's joint density is its own: the search would return the independent assignment.
  if (resolvedAssignmentScore(options_) != AssignmentScore::Joint || !pending_ || !pending_->marginal ||
      records_.size() - first < 2) {
    return independent;
  }
  // (§4, "Joint compatibility") The same hypotheses scored by the joint density of the pairings' innovations.
  const Key pose = poseKeys_.back();
  std::vector<JointAssignmentRow> rows;
  std::vector<std::vector<FactorPtr>> factorOf;  // per row and candidate: the pairing's factor, built once
  for (std::size_t r = first; r < records_.size(); ++r) {
    const DetectionRecord& record = records_[r];
    JointAssignmentRow& row = rows.emplace_back();
    row.candidates = record.candidates;
    row.pairingLogLikelihoods = record.logLikelihoods;  // (the geometric and label terms of findCandidates)
    for (int j : record.candidates) {
      row.labelLogLikelihoods.push_back(std::log(landmarks_[j].classBelief.predictive(record.semanticLikelihoods)));
    }
    row.unassignedLogLikelihood = record.unassignedLogLikelihood;
    row.labelPriorLogLikelihood = std::log(labelPrior(record));
    const SharedNoiseModel noise = factory_.detectionNoise(record.measurement);
    row.logNormalizer = noise->logNormalizer();
    std::vector<FactorPtr>& factors = factorOf.emplace_back();
    for (int j : record.candidates) {
      factors.push_back(factory_.detectionFactor(pose, landmarks_[j].key, record.measurement, noise));
    }
  }
  const JointDensity density = [&](const std::vector<std::pair<std::size_t, int>>& pairings) {
    std::vector<FactorPtr> factors;
    std::vector<Key> keys = {pose};
    for (const auto& [row, landmark] : pairings) {
      const std::vector<int>& candidates = rows[row].candidates;
      const auto c = std::find(candidates.begin(), candidates.end(), landmark) - candidates.begin();
      factors.push_back(factorOf[row][static_cast<std::size_t>(c)]);
      keys.push_back(landmarks_[landmark].key);
    }
    return linearizedLikelihood(factors, smoother_->estimate(), pending_->marginal->restrictedTo(keys));
  };
  const JointAssignment found = jointlyCompatibleAssignment(rows, density, gate_, independent);
  if (!found.exhaustive) ++jointSearchesStopped_;
  return found.landmarkOfRow;
}

std::vector<int> SemanticSlam::independentAssignment(std::size_t first) const {
  // (§4) Rows: the step's detections. Columns: every landmark some detection gated, then one unassigned column per
  // detection, open to that detection only. Weights: log-likelihoods; the maximum-weight assignment is the most
  // likely joint association with at most one detection per landmark.
  const std::size_t rows = records_.size() - first;
  std::vector<int> columnLandmark;
  std::map<int, int> columnOf;
  std::vector<double> allowed;
  for (std::size_t r = first; r < records_.size(); ++r) {
    for (int j : records_[r].candidates) {
      if (columnOf.emplace(j, static_cast<int>(columnLandmark.size())).second) columnLandmark.push_back(j);
    }
    allowed.insert(allowed.end(), records_[r].logLikelihoods.begin(), records_[r].logLikelihoods.end());
    allowed.push_back(records_[r].unassignedLogLikelihood);
  }
  const int landmarkColumns = static_cast<int>(columnLandmark.size());
  Matrix weights = Matrix::Constant(static_cast<Eigen::Index>(rows), landmarkColumns + static_cast<Eigen::Index>(rows),
                                    forbiddenWeight(allowed));
  for (std::size_t i = 0; i < rows; ++i) {
    const DetectionRecord& record = records_[first + i];
    for (std::size_t c = 0; c < record.candidates.size(); ++c) {
      weights(static_cast<Eigen::Index>(i), columnOf.at(record.candidates[c])) = record.logLikelihoods[c];
    }
    weights(static_cast<Eigen::Index>(i), landmarkColumns + static_cast<Eigen::Index>(i)) = record.unassignedLogLikelihood;
  }
  const Assignment assignment = maximumWeightAssignment(weights);
  std::vector<int> assignedLandmark(rows, -1);
  for (std::size_t i = 0; i < rows; ++i) {
    const int column = assignment.rowToColumn[i];
    if (column >= 0 && column < landmarkColumns) assignedLandmark[i] = columnLandmark[column];
  }
  return assignedLandmark;
}

std::vector<std::size_t> SemanticSlam::anchoringDetections() const {
  if (!pending_) throw std::logic_error("anchoringDetections: no step begun");
  std::vector<std::size_t> anchoring;
  if (!pending_->marginal) return anchoring;  // no landmark to pair with
  for (std::size_t i = 0; i < pending_->assignedLandmark.size(); ++i) {
    const int landmark = pending_->assignedLandmark[i];
    if (landmark < 0) continue;
    const std::size_t r = pending_->first + i;
    const Detection& detection = records_[r].measurement;
    // ln N(z; ẑ, S) = −½ d² − ½ m ln 2π − ½ ln det S and the detection's logNormalizer n_R = ½ m ln 2π + ½ ln det R,
    // so I = ½ ln det(S R⁻¹) = −(ln N + ½ d² + n_R) (docs/association-front-end.md §10).
    const SharedNoiseModel noise = factory_.detectionNoise(detection);
    const LinearizedLikelihood geometric =
        geometricLikelihood(*pending_->marginal, landmarks_[landmark], detection, noise);
    const double logNormalizer = noise->logNormalizer();
    const double information = -(geometric.logLikelihood + 0.5 * geometric.innovationChi2 + logNormalizer);
    if (information > options_.anchoringInformation) anchoring.push_back(r);
  }
  return anchoring;
}

void SemanticSlam::keepApart(const std::vector<std::size_t>& records) {
  if (!pending_) throw std::logic_error("keepApart: no step begun");
  for (std::size_t r : records) {
    if (r < pending_->first || r - pending_->first >= pending_->assignedLandmark.size()) {
      throw std::invalid_argument("keepApart: record " + std::to_string(r) + " is not of the begun step");
    }
    int& landmark = pending_->assignedLandmark[r - pending_->first];
    if (landmark < 0) continue;
    pending_->keptApart.push_back(r);
    landmark = -1;
  }
}

void SemanticSlam::keepMergesApart() {
  if (!pending_) throw std::logic_error("keepMergesApart: no step begun");
  pending_->mergesKeptApart = true;
}

void SemanticSlam::keepApartFromMapped(int landmark, int landmarksBeforeStep) {
  for (int j = 0; j < landmarksBeforeStep; ++j) {
    if (j == landmark || !lifecycle_.active(j)) continue;
    landmarks_[static_cast<std::size_t>(landmark)].distinctFrom.push_back(j);
    landmarks_[static_cast<std::size_t>(j)].distinctFrom.push_back(landmark);
  }
}

double SemanticSlam::mergeInformation(int p, double halfLogDetDifference) const {
  std::optional<std::size_t> last;  // p's last detection: the one that started it, or the last assigned to it
  for (std::size_t r : landmarks_[static_cast<std::size_t>(p)].records) {
    if (records_[r].createdLandmark == p || records_[r].assigned == p) last = r;
  }
  if (!last) throw std::logic_error("mergeInformation: landmark " + std::to_string(p) + " holds no detection");
  const Detection& detection = records_[*last].measurement;
  const int d = factory_.dimension();
  const Eigen::LLT<Matrix> cholesky(detection.covariance.topLeftCorner(d, d));
  const double halfLogDetSensor = cholesky.matrixLLT().diagonal().array().log().sum();
  // ½ ln det(2 J R Jᵀ) = (d/2) ln 2 + ½ ln det R + ln J
  const double halfLogDetTwoWorld =
      0.5 * d * std::log(2.0) + halfLogDetSensor + unassigned_.logBackProjectionJacobian(detection);
  return halfLogDetDifference - halfLogDetTwoWorld;
}

bool SemanticSlam::pairElsewhere(const std::vector<std::size_t>& records) {
  if (!pending_) throw std::logic_error("pairElsewhere: no step begun");
  for (std::size_t r : records) {
    if (r < pending_->first || r - pending_->first >= pending_->assignedLandmark.size()) {
      throw std::invalid_argument("pairElsewhere: record " + std::to_string(r) + " is not of the begun step");
    }
    const int given = pending_->assignedLandmark[r - pending_->first];
    if (given < 0) continue;
    DetectionRecord& record = records_[r];
    const auto at = std::find(record.candidates.begin(), record.candidates.end(), given);
    if (at == record.candidates.end()) throw std::logic_error("pairElsewhere: the assigned landmark is no candidate");
    const auto c = at - record.candidates.begin();
    record.candidates.erase(at);
    record.logLikelihoods.erase(record.logLikelihoods.begin() + c);
    if (!record.weights.empty()) record.weights.erase(record.weights.begin() + c);
  }
  pending_->assignedLandmark = jointAssignment(pending_->first);
  return std::any_of(records.begin(), records.end(),
                     [this](std::size_t r) { return pending_->assignedLandmark[r - pending_->first] >= 0; });
}

void SemanticSlam::applyJointAssignment(std::size_t first, const std::vector<int>& assignedLandmark) {
  const std::size_t rows = records_.size() - first;
  // Exclusion: a detection's remaining candidates are those no other detection of the step was assigned.
  for (std::size_t i = 0; i < rows; ++i) {
    DetectionRecord& record = records_[first + i];
    if (assignedLandmark[i] < 0) {
      record.candidates.clear();  // unassigned: it starts a landmark (provisional rules: §5, to come)
      record.logLikelihoods.clear();
      record.weights.clear();
      continue;
    }
    record.assigned = assignedLandmark[i];
    std::vector<int> candidates;
    std::vector<double> logLikelihoods;
    for (std::size_t c = 0; c < record.candidates.size(); ++c) {
      const int j = record.candidates[c];
      const bool takenByAnother = j != assignedLandmark[i] &&
                                  std::find(assignedLandmark.begin(), assignedLandmark.end(), j) != assignedLandmark.end();
      const bool single = options_.strategy == AssociationStrategy::MaximumLikelihood && j != assignedLandmark[i];
      if (takenByAnother || single) continue;
      candidates.push_back(j);
      logLikelihoods.push_back(record.logLikelihoods[c]);
    }
    record.candidates = std::move(candidates);
    record.logLikelihoods = std::move(logLikelihoods);
    record.weights = normalizeLogWeights(record.logLikelihoods);
  }
}

FactorPtr SemanticSlam::gpdaFactor(const DetectionRecord& record, int landmark, double weight) const {
  // Information scaled by the weight: standard deviations divided by √w.
  return factory_.detectionFactor(poseKeys_[record.step], landmarks_[landmark].key, record.measurement,
                                  1.0 / std::sqrt(std::max(weight, options_.minimumGpdaWeight)));
}

std::vector<FactorPtr> SemanticSlam::associationFactors(DetectionRecord& record) const {
  const Key pose = poseKeys_[record.step];
  const int best = record.candidates[bestCandidate(record)];
  switch (options_.strategy) {
    case AssociationStrategy::MaximumLikelihood:
      return {factory_.detectionFactor(pose, landmarks_[best].key, record.measurement)};
    case AssociationStrategy::Gpda: {
      std::vector<FactorPtr> factors;
      for (std::size_t c = 0; c < record.candidates.size(); ++c) {
        factors.push_back(gpdaFactor(record, record.candidates[c], record.weights[c]));
      }
      return factors;
    }
    case AssociationStrategy::MaxMixture:
    case AssociationStrategy::MaxMixtureNullHypothesis: {
      const bool withNull = options_.strategy == AssociationStrategy::MaxMixtureNullHypothesis;
      std::vector<MaxMixtureFactor::Component> components;
      for (std::size_t c = 0; c < record.candidates.size(); ++c) {
        components.push_back({factory_.detectionFactor(pose, landmarks_[record.candidates[c]].key, record.measurement),
                              record.weights[c] * (withNull ? 1.0 - options_.nullWeight : 1.0), std::nullopt});
      }
      if (withNull) {  // the best candidate's factor widened (B, sec. IV-C): the mixture evaluates it once for both
        components.push_back({factory_.detectionFactor(pose, landmarks_[best].key, record.measurement,
                                                       options_.nullSigmaScale),
                              options_.nullWeight,
                              MaxMixtureFactor::Widening{bestCandidate(record), options_.nullSigmaScale}});
      }
      record.mixture = std::make_shared<const MaxMixtureFactor>(std::move(components));
      return {record.mixture};
    }
    case AssociationStrategy::Known: break;
  }
  throw std::logic_error("associationFactors: strategy without candidates");
}

bool SemanticSlam::reweight(DetectionRecord& record) {
  if (record.candidates.size() < 2) return false;
  const Values& estimate = smoother_->estimate();
  const Key pose = poseKeys_[record.step];
  std::vector<double> logWeights;
  for (int landmark : record.candidates) {
    const std::vector<FactorPtr> factor = {factory_.detectionFactor(pose, landmarks_[landmark].key, record.measurement)};
    const int p = factory_.poseTangentDimension(), l = factory_.landmarkTangentDimension();
    const JointMarginal pointEstimate({pose, landmarks_[landmark].key}, {p, l}, Matrix::Zero(p + l, p + l));
    const double semantic = landmarks_[landmark].classBelief.predictive(record.semanticLikelihoods);
    logWeights.push_back(linearizedLikelihood(factor, estimate, pointEstimate).logLikelihood + std::log(semantic));
  }
  const std::vector<double> weights = normalizeLogWeights(logWeights);
  bool changed = false;
  for (std::size_t c = 0; c < weights.size(); ++c) {
    const double before = std::max(record.weights[c], options_.minimumGpdaWeight);
    const double after = std::max(weights[c], options_.minimumGpdaWeight);
    if (std::abs(std::log(after / before)) > 1e-3) {
      smoother_->replaceFactor(record.factors[c], gpdaFactor(record, record.candidates[c], weights[c]));
      changed = true;
    }
  }
  record.weights = weights;
  return changed;
}

void SemanticSlam::expectationMaximization(std::size_t firstRecord, int iterations) {
  for (int iteration = 0; iteration < iterations; ++iteration) {
    bool changed = false;
    for (std::size_t r = firstRecord; r < records_.size(); ++r) {
      if (!records_[r].createdLandmark && !records_[r].candidates.empty()) changed |= reweight(records_[r]);
    }
    if (!changed) return;
    smoother_->update();
  }
}

std::vector<FactorPtr> SemanticSlam::recordFactors(DetectionRecord& record) const {
  record.mixture = nullptr;
  if (record.knownLandmark) {
    return {factory_.detectionFactor(poseKeys_[record.step], landmarks_[*record.knownLandmark].key, record.measurement)};
  }
  if (record.createdLandmark) {
    return {factory_.detectionFactor(poseKeys_[record.step], landmarks_[*record.createdLandmark].key,
                                     record.measurement)};
  }
  if (record.candidates.empty()) return {};
  return associationFactors(record);
}

void SemanticSlam::applyEdits(std::vector<std::size_t> touched, std::vector<FactorIndex> removed,
                              const std::vector<int>& heldByPrior, const Values& newLandmarks) {
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  FactorGraph added;
  std::vector<std::size_t> addedBy;  // the record of each added factor
  for (std::size_t r : touched) {
    DetectionRecord& record = records_[r];
    removed.insert(removed.end(), record.factors.begin(), record.factors.end());
    record.factors.clear();
    for (const FactorPtr& factor : recordFactors(record)) {
      added.add(factor);
      addedBy.push_back(r);
    }
  }
  const Values& estimate = smoother_->estimate();
  auto valueOf = [&](int landmark) -> const Value& {
    const Key key = landmarks_[landmark].key;
    return newLandmarks.exists(key) ? newLandmarks.value(key) : estimate.value(key);
  };
  for (int landmark : heldByPrior) {  // after the records' factors
    added.add(landmarkPrior(landmark, valueOf(landmark), weakPriorSigma()));
  }
  if (orientationUnobservable_) {  // last: like every new landmark's (step 2)
    for (const auto& [key, value] : newLandmarks) {
      added.add(landmarkPrior(static_cast<int>(Symbol(key).index()), value, kUnconstrainedSigma));
    }
  }
  if (added.size() == 0 && removed.empty()) return;
  const std::vector<FactorIndex> indices = smoother_->update(added, newLandmarks, removed);
  for (std::size_t i = 0; i < addedBy.size(); ++i) records_[addedBy[i]].factors.push_back(indices[i]);
  for (std::size_t i = 0; i < heldByPrior.size(); ++i) {
    landmarks_[heldByPrior[i]].weakPrior = indices[addedBy.size() + i];
  }
}

FactorPtr SemanticSlam::landmarkPrior(int landmark, const Value& value, double positionSigma) const {
  const int dimension = factory_.landmarkTangentDimension();
  const int position = factory_.dimension();  // the tangent's first entries: translation (MeasurementLog.h)
  Vector variances = Vector::Constant(dimension, std::numbers::pi * std::numbers::pi);
  variances.head(std::min(position, dimension)).setConstant(positionSigma * positionSigma);
  return factory_.landmarkPriorFactor(landmarks_[landmark].key,
                                      LandmarkPrior{-1, toLandmarkState(value), Matrix(variances.asDiagonal())});
}

std::optional<double> SemanticSlam::orientationPriorPositionScore() const {
  if (!orientationUnobservable_) return std::nullopt;
  return factory_.dimension() * std::log(2.0 * std::numbers::pi * kUnconstrainedSigma * kUnconstrainedSigma);
}

double SemanticSlam::bestPosterior(const DetectionRecord& record) {
  const int best = bestCandidate(record);
  if (record.logLikelihoods.size() != record.candidates.size()) return record.weights[best];  // threshold rule
  std::vector<double> logWeights = record.logLikelihoods;
  logWeights.push_back(record.unassignedLogLikelihood);
  return normalizeLogWeights(logWeights)[best];
}

bool SemanticSlam::removeCandidate(DetectionRecord& record, int landmark) {
  const auto found = std::find(record.candidates.begin(), record.candidates.end(), landmark);
  if (found == record.candidates.end()) return false;
  const auto c = found - record.candidates.begin();
  record.candidates.erase(found);
  record.weights.erase(record.weights.begin() + c);
  if (!record.logLikelihoods.empty()) record.logLikelihoods.erase(record.logLikelihoods.begin() + c);
  if (record.assigned == landmark) record.assigned.reset();
  if (!record.candidates.empty()) {
    record.weights = record.logLikelihoods.empty() ? normalizeWeights(record.weights)
                                                   : normalizeLogWeights(record.logLikelihoods);
  }
  return true;
}

std::vector<std::size_t> SemanticSlam::recordsOn(int landmark) const {
  std::vector<std::size_t> on;
  for (std::size_t r : landmarks_[landmark].records) {
    const DetectionRecord& record = records_[r];
    if (record.createdLandmark == landmark || record.assigned == landmark || record.knownLandmark == landmark) {
      on.push_back(r);
    }
  }
  std::sort(on.begin(), on.end());  // records are numbered in step order
  return on;
}

std::vector<int> SemanticSlam::stepsOn(int landmark) const {
  std::vector<int> steps;
  for (std::size_t r : recordsOn(landmark)) steps.push_back(records_[r].step);
  return steps;
}

void SemanticSlam::dropLandmark(int landmark, std::vector<std::size_t>& touched) {
  // (§5) Every detection on it is left on no landmark; the variable stays, held by its weak prior alone.
  lifecycle_.drop(landmark);
  for (std::size_t r : landmarks_[landmark].records) {
    DetectionRecord& record = records_[r];
    if (record.createdLandmark == landmark) {
      record.createdLandmark.reset();
      record.rejected = true;
    } else {
      if (!removeCandidate(record, landmark)) continue;
    }
    touched.push_back(r);
  }
  landmarks_[landmark].records.clear();
}

void SemanticSlam::mergeLandmark(int landmark, int into, std::vector<std::size_t>& touched,
                                 std::vector<FactorIndex>& removed) {
  // (§5) Its detections move to `into`, their labels with them, and count towards confirming it; the variable
  // stays, held by its weak prior alone.
  lifecycle_.merge(landmark, into);
  Landmark& target = landmarks_[into];
  const std::vector<std::size_t> recordsMoved = recordsOn(landmark);
  for (std::size_t r : landmarks_[landmark].records) {
    DetectionRecord& record = records_[r];
    if (record.createdLandmark == landmark) {
      record.createdLandmark = into;
      target.classBelief.update(record.semanticLikelihoods);
    } else {
      const auto found = std::find(record.candidates.begin(), record.candidates.end(), landmark);
      if (found == record.candidates.end()) continue;
      const auto c = found - record.candidates.begin();
      target.classBelief.update(record.semanticLikelihoods, record.weights[c]);
      const bool wasAssigned = record.assigned == landmark;
      if (std::find(record.candidates.begin(), record.candidates.end(), into) != record.candidates.end()) {
        removeCandidate(record, landmark);  // already a candidate (and in target.records): one entry, its own
        if (wasAssigned) record.assigned = into;
        touched.push_back(r);
        continue;
      }
      *found = into;  // its likelihood under the landmark it merged into: the one computed for the merged one
      if (wasAssigned) record.assigned = into;
    }
    target.records.push_back(r);
    touched.push_back(r);
  }
  landmarks_[landmark].records.clear();
  for (std::size_t r : recordsMoved) confirmIfDue(into, r, removed);
}

Vector SemanticSlam::robotPosition(int step, const Values& newValues) const {
  const Key pose = poseKeys_[static_cast<std::size_t>(step)];
  return MeasurementFactory::positionOf(newValues.exists(pose) ? newValues.value(pose)
                                                               : smoother_->estimate().value(pose));
}

bool SemanticSlam::countSighting(int landmark, std::size_t r) {
  const DetectionRecord& record = records_[r];
  const double positionSigma =
      lifecycle_.rule().viewpointSigmas > 0.0 ? factory_.detectionPositionSigma(record.measurement) : 0.0;
  return lifecycle_.observe(landmark, stepTimes_[static_cast<std::size_t>(record.step)], robotPosition(record.step),
                            positionSigma);
}

void SemanticSlam::confirmIfDue(int landmark, std::size_t r, std::vector<FactorIndex>& removed) {
  if (!countSighting(landmark, r) || !landmarks_[landmark].weakPrior) {
    return;
  }
  removed.push_back(*landmarks_[landmark].weakPrior);  // a confirmed landmark stands on its detections
  landmarks_[landmark].weakPrior.reset();
}

void SemanticSlam::mergeDuplicateLandmarks(const std::vector<bool>& seen, int landmarksBeforeStep,
                                           bool mergesKeptApart, std::vector<std::size_t>& touched,
                                           std::vector<FactorIndex>& removed, std::vector<int>& heldByPrior) {
  // (§5) A landmark P merges into an active landmark L when the difference of their positions passes the χ² gate
  // under their joint marginal and "one landmark" explains it better than a second, uniformly placed one:
  //     N(p_P − p_L; 0, Σ_d) · M Σ_c P(c | P) P(c | L)  >  ρ,
  // Σ_d = J_P Σ_PP J_Pᵀ + J_L Σ_LL J_Lᵀ − J_P Σ_PL J_Lᵀ − J_L Σ_LP J_Pᵀ (J: tangent → world position), ρ the
  // unassigned hypothesis's Cartesian density. Never when a step has a detection on each (exclusion, §4).
  // Tested: every provisional landmark (against the confirmed ones and the older provisional ones), and every
  // confirmed landmark seen at this step (§5c: against the other confirmed ones; of a confirmed pair the newer
  // merges into the older, and its variable, left without factors, gets the weak prior of a provisional one).
  const Values& estimate = smoother_->estimate();
  std::vector<int> movers, nearby;
  for (int j = 0; j < landmarks(); ++j) {
    if (lifecycle_.provisional(j) || (lifecycle_.active(j) && seen[static_cast<std::size_t>(j)])) movers.push_back(j);
  }
  if (movers.empty()) return;
  const double range = unassigned_.maxRange();
  std::vector<Vector> positions(static_cast<std::size_t>(landmarks()));  // of the active landmarks, read once
  for (int j = 0; j < landmarks(); ++j) {
    if (lifecycle_.active(j)) positions[j] = MeasurementFactory::positionOf(estimate.value(landmarks_[j].key));
  }
  auto position = [&](int j) -> const Vector& { return positions[static_cast<std::size_t>(j)]; };
  for (int j = 0; j < landmarks(); ++j) {
    if (!lifecycle_.active(j) || lifecycle_.provisional(j) || std::binary_search(movers.begin(), movers.end(), j)) {
      continue;
    }
    for (int p : movers) {
      if ((position(j) - position(p)).norm() <= range) {
        nearby.push_back(j);
        break;
      }
    }
  }
  if (nearby.empty() && movers.size() < 2) return;  // nothing to merge into: no marginal to take
  const auto targetsOf = [&](int p) {
    std::vector<int> targets;
    for (int l : nearby) {
      if (lifecycle_.active(l)) targets.push_back(l);
    }
    const bool provisional = lifecycle_.provisional(p);
    for (int q : movers) {
      if (q == p || !lifecycle_.active(q)) continue;
      // A provisional landmark goes into a confirmed one or an older provisional one; a confirmed one is tested
      // against confirmed ones only (a provisional one is tested against it in its own turn).
      if (provisional ? (!lifecycle_.provisional(q) || q < p) : !lifecycle_.provisional(q)) targets.push_back(q);
    }
    return targets;
  };
  // What rules a pair out without the joint marginal: too far apart, split apart (§5d), seen at one step
  // (exclusion, §4), or a difference beyond the gate's reach. The gate below needs d = p_P − p_L within
  // √T √λmax(Σ_d), and the standard deviations of a difference add whatever the correlation: √λmax(Σ_d) ≤ σ_P + σ_L,
  // with σ the pre-selection's spread bounds (§7, each at least √λmax of its landmark's position block). A step on
  // which every pair is ruled out takes no joint marginal.
  const double gateRadius = std::sqrt(gate_.threshold(factory_.dimension()));
  const auto mayMerge = [&](int p, const std::vector<int>& stepsOfP, int l) {
    const double distance = (position(p) - position(l)).norm();
    if (distance > range) return false;
    const std::vector<int>& distinct = landmarks_[p].distinctFrom;
    if (std::find(distinct.begin(), distinct.end(), l) != distinct.end()) return false;
    // No bound for a landmark the pre-selection does not track yet (born at this step), nor without pre-selection.
    const std::optional<double> spreadP = preselection_.spread(p), spreadL = preselection_.spread(l);
    if (spreadP && spreadL && distance > gateRadius * (*spreadP + *spreadL)) return false;
    const std::vector<int> stepsOfL = stepsOn(l);
    std::vector<int> shared;
    std::set_intersection(stepsOfP.begin(), stepsOfP.end(), stepsOfL.begin(), stepsOfL.end(),
                          std::back_inserter(shared));
    return shared.empty();
  };
  // The joint marginal of the landmarks of the pairs left: every pair of a mover and another mover or a nearby
  // landmark, whatever targetsOf's order says now, since a merge below may confirm a provisional landmark. A merge
  // never brings back a pair ruled out here: positions, spreads and splits stay as they are, a merged landmark
  // leaves, and one that receives detections shares more steps.
  std::vector<bool> inPair(static_cast<std::size_t>(landmarks()), false);
  for (int p : movers) {
    const std::vector<int> stepsOfP = stepsOn(p);
    for (const std::vector<int>* group : {&movers, &nearby}) {
      for (int l : *group) {
        if (l == p || !mayMerge(p, stepsOfP, l)) continue;
        inPair[static_cast<std::size_t>(p)] = inPair[static_cast<std::size_t>(l)] = true;
      }
    }
  }
  std::vector<Key> keys;
  for (const std::vector<int>* group : {&movers, &nearby}) {
    for (int j : *group) {
      if (inPair[static_cast<std::size_t>(j)]) keys.push_back(landmarks_[j].key);
    }
  }
  if (keys.empty()) return;
  const JointMarginal marginal = smoother_->jointMarginal(keys);
  const int d = factory_.dimension();
  auto toWorld = [&](int j) -> Matrix {  // J: the landmark tangent's position part in the world frame
    const Value& value = estimate.value(landmarks_[j].key);
    Matrix jacobian = Matrix::Zero(d, factory_.landmarkTangentDimension());
    if (const auto* se2 = std::get_if<SE2>(&value)) jacobian.leftCols(2) = se2->rotation().matrix();
    else if (const auto* se3 = std::get_if<SE3>(&value)) jacobian.leftCols(3) = se3->rotation().matrix();
    else jacobian.leftCols(d).setIdentity();
    return jacobian;
  };
  const double classes = header_.classes > 0 ? header_.classes : 1;
  for (int p : movers) {
    if (!lifecycle_.active(p)) continue;  // merged away earlier in this loop
    const bool provisional = lifecycle_.provisional(p);
    const std::vector<int> stepsOfP = stepsOn(p);
    std::optional<int> best;
    double bestScore = unassigned_.logCartesianDensity();
    double bestHalfLogDetDifference = 0.0;
    for (int l : targetsOf(p)) {
      if (!mayMerge(p, stepsOfP, l)) continue;
      const Vector difference = position(p) - position(l);
      const JointMarginal pair = marginal.restrictedTo({landmarks_[p].key, landmarks_[l].key});
      const Matrix jp = toWorld(p), jl = toWorld(l);
      const Matrix cross = jp * pair.block(landmarks_[p].key, landmarks_[l].key) * jl.transpose();
      const Matrix covariance = jp * pair.block(landmarks_[p].key, landmarks_[p].key) * jp.transpose() +
                                jl * pair.block(landmarks_[l].key, landmarks_[l].key) * jl.transpose() - cross -
                                cross.transpose();
      const Eigen::LLT<Matrix> cholesky(covariance);
      if (cholesky.info() != Eigen::Success) continue;
      const Vector whitened = cholesky.matrixL().solve(difference);
      const double chi2 = whitened.squaredNorm();
      if (chi2 > gate_.threshold(d)) continue;
      const Vector logDiagonal = cholesky.matrixLLT().diagonal().array().log();
      const double logGaussian = -0.5 * chi2 - 0.5 * d * std::log(2.0 * std::numbers::pi) - logDiagonal.sum();
      const double sameClass = classes * landmarks_[p].classBelief.probabilities().dot(
                                             landmarks_[l].classBelief.probabilities());
      if (!(sameClass > 0.0)) continue;
      const double score = logGaussian + std::log(sameClass);
      if (score <= bestScore) continue;
      best = l;
      bestScore = score;
      bestHalfLogDetDifference = logDiagonal.sum();
    }
    if (!best) continue;
    if (provisional && mergesKeptApart && *best < landmarksBeforeStep &&
        mergeInformation(p, bestHalfLogDetDifference) > options_.anchoringInformation) {
      keepApartFromMapped(p, landmarksBeforeStep);  // (§10, branch B) a loop closure by a merge, refused
      continue;
    }
    if (provisional) {
      mergeLandmark(p, *best, touched, removed);
    } else {
      const int newer = std::max(p, *best), older = std::min(p, *best);
      mergeLandmark(newer, older, touched, removed);
      heldByPrior.push_back(newer);
    }
  }
}

void SemanticSlam::updateLifecycle(int k, int landmarksBeforeStep, bool mergesKeptApart) {
  std::vector<std::size_t> touched;
  std::vector<FactorIndex> removed;
  // Confirmations: the step's assigned detections count towards M; a confirmed landmark loses its weak prior.
  std::vector<bool> seen(static_cast<std::size_t>(landmarks()), false);
  for (std::size_t r = firstRecordOfStep_[static_cast<std::size_t>(k)]; r < records_.size(); ++r) {
    if (!records_[r].assigned) continue;
    const int j = *records_[r].assigned;
    seen[static_cast<std::size_t>(j)] = true;
    confirmIfDue(j, r, removed);
  }
  // Drops: a provisional landmark born before this step, in the field now and not seen, uses up its patience.
  const Values& estimate = smoother_->estimate();
  const Value& robot = estimate.value(poseKeys_[static_cast<std::size_t>(k)]);
  for (int j = 0; j < landmarksBeforeStep; ++j) {
    if (!lifecycle_.provisional(j) || seen[static_cast<std::size_t>(j)]) continue;
    const Vector inSensor = factory_.positionInSensorFrame(robot, estimate.value(landmarks_[j].key));
    if (unassigned_.inField(inSensor) && lifecycle_.passedInField(j)) dropLandmark(j, touched);
  }
  std::vector<int> heldByPrior;
  mergeDuplicateLandmarks(seen, landmarksBeforeStep, mergesKeptApart, touched, removed, heldByPrior);
  applyEdits(std::move(touched), std::move(removed), heldByPrior);
  if (options_.labelSplit) splitLandmarks(seen);
}

void SemanticSlam::rebuildClassBelief(int landmark) {
  Landmark& target = landmarks_[landmark];
  target.classBelief = ClassBelief(header_.classes);
  for (std::size_t r : target.records) {
    const DetectionRecord& record = records_[r];
    if (record.createdLandmark == landmark) {
      target.classBelief.update(record.semanticLikelihoods);
      continue;
    }
    const auto found = std::find(record.candidates.begin(), record.candidates.end(), landmark);
    if (found != record.candidates.end()) {
      target.classBelief.update(record.semanticLikelihoods, record.weights[found - record.candidates.begin()]);
    }
  }
}

void SemanticSlam::splitLandmarks(const std::vector<bool>& seen) {
  // (§5d) The detections on a landmark (started it or assigned to it), linearised with their poses held fixed at
  // the estimate, and their labels: LandmarkSplit.h decides. The second object becomes a new landmark at its own
  // position, provisional until its moved detections confirm it by the M-of-N rule; the two never merge again.
  if (header_.semantic == SemanticKind::None || header_.classes < 2) return;
  const Values& estimate = smoother_->estimate();
  const int d = factory_.dimension();
  std::vector<std::size_t> touched;
  std::vector<int> heldByPrior;
  Values newLandmarks;
  const int existing = landmarks();
  for (int j = 0; j < existing; ++j) {
    if (!seen[static_cast<std::size_t>(j)] || !lifecycle_.active(j)) continue;
    std::vector<std::size_t> on;  // the records on j
    std::vector<SplitEvidence> evidence;
    LinearizedFactor linearized;
    std::vector<std::size_t> records = landmarks_[j].records;
    std::sort(records.begin(), records.end());  // in time order: a merge appends older records
    for (std::size_t r : records) {
      const DetectionRecord& record = records_[r];
      const bool assigned = record.assigned == j && std::find(record.candidates.begin(), record.candidates.end(),
                                                              j) != record.candidates.end();
      if (record.createdLandmark != j && !assigned) continue;
      const FactorPtr factor = factory_.detectionFactor(poseKeys_[static_cast<std::size_t>(record.step)],
                                                        landmarks_[j].key, record.measurement);
      factor->linearize(estimate, linearized);
      const auto position = std::find(factor->keys().begin(), factor->keys().end(), landmarks_[j].key);
      const Matrix& jacobian = linearized.jacobians[static_cast<std::size_t>(position - factor->keys().begin())];
      evidence.push_back({record.semanticLikelihoods, linearized.whitenedError, jacobian.leftCols(d)});
      on.push_back(r);
    }
    const std::optional<LandmarkSplitDecision> split = bestLandmarkSplit(evidence, unassigned_.logCartesianDensity());
    if (!split) continue;
    Vector tangent = Vector::Zero(factory_.landmarkTangentDimension());
    tangent.head(d) = split->secondDelta;
    const Value initial = retract(estimate.value(landmarks_[j].key), tangent);
    std::vector<std::size_t> moved;
    for (std::size_t i = 0; i < on.size(); ++i) {
      if (split->second[i]) moved.push_back(on[i]);
    }
    const int second = addLandmark(initial, std::nullopt, newLandmarks,  // enters with the edit below
                                   stepTimes_[static_cast<std::size_t>(records_[moved.front()].step)]);
    landmarks_[j].distinctFrom.push_back(second);
    landmarks_[second].distinctFrom.push_back(j);
    for (std::size_t r : moved) {
      DetectionRecord& record = records_[r];
      if (record.createdLandmark == j) {
        record.createdLandmark = second;
      } else {
        *std::find(record.candidates.begin(), record.candidates.end(), j) = second;  // its likelihood stays
        record.assigned = second;
      }
      landmarks_[second].records.push_back(r);
      touched.push_back(r);
    }
    std::erase_if(landmarks_[j].records,
                  [&](std::size_t r) { return std::find(moved.begin(), moved.end(), r) != moved.end(); });
    rebuildClassBelief(j);
    rebuildClassBelief(second);
    bool confirmed = false;  // the moved detections after the first count towards M, as a merge's do
    for (std::size_t i = 1; i < moved.size(); ++i) confirmed |= countSighting(second, moved[i]);
    if (!confirmed && lifecycle_.provisional(second)) heldByPrior.push_back(second);
  }
  applyEdits(std::move(touched), {}, heldByPrior, newLandmarks);
}

bool SemanticSlam::repairExclusion(std::size_t first, std::size_t end) {
  // (§4) Per step: the landmark each mixture uses at the estimate; where two share one, the one whose component
  // costs more (½ chi2 + log-normaliser − log weight, the mixture's own cost) loses it.
  const Values& estimate = smoother_->estimate();
  std::vector<std::size_t> touched;
  std::size_t r = first;
  while (r < end) {
    const int step = records_[r].step;
    std::map<int, std::vector<std::pair<double, std::size_t>>> users;  // landmark → (cost, record)
    for (; r < end && records_[r].step == step; ++r) {
      const DetectionRecord& record = records_[r];
      if (!record.mixture) continue;
      const auto& mixture = static_cast<const MaxMixtureFactor&>(*record.mixture);
      const int active = mixture.activeComponent(estimate);
      if (active >= static_cast<int>(record.candidates.size())) continue;  // the null hypothesis
      const MaxMixtureFactor::Component& component = mixture.components()[static_cast<std::size_t>(active)];
      const double cost = 0.5 * component.factor->chi2(estimate) + component.factor->logNormalizer().value_or(0.0) -
                          std::log(component.weight);
      users[record.candidates[static_cast<std::size_t>(active)]].push_back({cost, r});
    }
    for (auto& [landmark, costs] : users) {
      if (costs.size() < 2) continue;
      std::sort(costs.begin(), costs.end());
      for (std::size_t i = 1; i < costs.size(); ++i) {
        removeCandidate(records_[costs[i].second], landmark);
        touched.push_back(costs[i].second);
      }
    }
  }
  if (touched.empty()) return false;
  applyEdits(std::move(touched), {});
  return true;
}

void SemanticSlam::finish() {
  if (options_.birth == BirthRule::Unassigned) {
    // (§5) The map holds confirmed landmarks only: what is still provisional at the end was seen too briefly.
    std::vector<std::size_t> touched;
    for (int j = 0; j < landmarks(); ++j) {
      if (lifecycle_.provisional(j)) dropLandmark(j, touched);
    }
    applyEdits(std::move(touched), {});
  }
  if (options_.strategy == AssociationStrategy::Gpda && !graphFollowsTruth()) expectationMaximization(0, 10);
  smoother_->converge();
  if (options_.birth == BirthRule::Unassigned) {
    while (repairExclusion(0, records_.size())) smoother_->converge();  // (§4) at the final estimate
  }
}

std::pair<std::optional<int>, double> SemanticSlam::chosenAssociation(const DetectionRecord& record) const {
  return chosenAssociation(record, smoother_->estimate());
}

std::pair<std::optional<int>, double> SemanticSlam::chosenAssociation(const DetectionRecord& record,
                                                                      const Values& estimate) const {
  if (record.knownLandmark) return {*record.knownLandmark, 1.0};
  if (record.createdLandmark) return {*record.createdLandmark, 1.0};
  if (record.onNoFactor()) return {std::nullopt, 1.0};
  if (record.mixture) {
    const auto& mixture = static_cast<const MaxMixtureFactor&>(*record.mixture);
    const int active = mixture.activeComponent(estimate);
    if (active >= static_cast<int>(record.candidates.size())) return {std::nullopt, options_.nullWeight};
    const double scale = options_.strategy == AssociationStrategy::MaxMixtureNullHypothesis ? 1.0 - options_.nullWeight : 1.0;
    return {record.candidates[active], record.weights[active] * scale};
  }
  const int best = argmax(record.weights);  // ml: the one candidate left; gpda: the most probable after its EM
  return {record.candidates[best], record.weights[best]};
}

std::vector<FactorIndex> SemanticSlam::weakPriors() const {
  std::vector<FactorIndex> priors;
  for (const Landmark& landmark : landmarks_) {
    if (landmark.weakPrior) priors.push_back(*landmark.weakPrior);
  }
  return priors;
}

std::optional<double> SemanticSlam::residualChi2(const DetectionRecord& record) const {
  const std::optional<int> landmark = chosenAssociation(record).first;
  if (!landmark) return std::nullopt;
  const Key pose = poseKeys_[static_cast<std::size_t>(record.step)];
  return factory_.detectionFactor(pose, landmarks_[*landmark].key, record.measurement)->chi2(smoother_->estimate());
}

RunResult SemanticSlam::result(bool withPoseCovariances) const {
  RunResult result;
  result.method = strategyName(options_.strategy);
  if (options_.birth == BirthRule::Threshold) result.method += "+threshold";  // paper B's own birth rule
  if (options_.decideOnTrueHistory) result.method += "@true-history";
  const Values& estimate = smoother_->estimate();
  for (Key pose : poseKeys_) {
    result.poses.push_back(toPose(estimate.value(pose)));
    if (withPoseCovariances) result.poseCovariances.push_back(smoother_->marginalCovariance(pose));
  }
  result.associations.resize(poseKeys_.size());
  for (std::size_t k = 0; k < poseKeys_.size(); ++k) {
    const std::size_t end = k + 1 < poseKeys_.size() ? firstRecordOfStep_[k + 1] : records_.size();
    for (std::size_t r = firstRecordOfStep_[k]; r < end; ++r) {
      result.associations[k].push_back(chosenAssociation(records_[r]).first);
    }
  }
  if (options_.decideOnTrueHistory) {
    result.historyDecisions.resize(poseKeys_.size());
    for (const DetectionRecord& record : records_) {
      result.historyDecisions[static_cast<std::size_t>(record.step)].push_back({record.decided, record.rightDecision});
    }
  }
  for (int j = 0; j < landmarks(); ++j) {
    if (!lifecycle_.active(j)) continue;  // dropped or merged (§5)
    const bool hasClasses = header_.semantic != SemanticKind::None;
    result.landmarks.push_back({j, toLandmarkState(estimate.value(landmarks_[j].key)),
                                hasClasses ? landmarks_[j].classBelief.probabilities() : Vector()});
  }
  return result;
}

}  // namespace semslam
