#include "semslam/slam/SemanticSlam.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "semslam/association/MarginalLikelihood.h"
#include "semslam/factors/MaxMixtureFactor.h"
#include "semslam/solve/HungarianAssignment.h"

namespace semslam {
namespace {

constexpr double kGaugeSigma = 1e-6;
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

Pose toPose(const Value& value) {
  if (const auto* se2 = std::get_if<SE2>(&value)) return *se2;
  return std::get<SE3>(value);
}

LandmarkState toLandmarkState(const Value& value) {
  return std::visit(
      [](const auto& v) -> LandmarkState {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, SO2> || std::is_same_v<V, SO3>) {
          throw std::logic_error("a landmark cannot be a rotation");
        } else {
          return v;
        }
      },
      value);
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
      unassigned_(header, options_.unassignedRate),
      smoother_(options_.smoother ? options_.smoother() : smootherFactory(SmootherKind::Incremental)()) {
  if (!(options_.nullWeight > 0.0 && options_.nullWeight < 1.0)) {
    throw std::invalid_argument("null-hypothesis weight must be in (0, 1)");
  }
  if (!(options_.nullSigmaScale >= 1.0)) throw std::invalid_argument("null-hypothesis sigma scale must be >= 1");
  if (options_.emWindow < 1 || options_.emIterations < 0) throw std::invalid_argument("bad EM window or iterations");
}

int SemanticSlam::addLandmark(const Value& value, std::optional<int> truthId, Values& values) {
  const int index = landmarks();
  const Key key = landmarkKey(static_cast<std::uint64_t>(index));
  landmarks_.push_back({key, ClassBelief(header_.classes)});
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

void SemanticSlam::addStep(const TimeStep& step) {
  // 1. Propagate.
  const int k = steps();
  const Key pose = poseKey(static_cast<std::uint64_t>(k));
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
  const bool known = options_.strategy == AssociationStrategy::Known;
  if (!step.detections.empty() && !known && !landmarks_.empty()) {
    // The candidates' weights need the marginal of the propagated pose: solve before associating. (Otherwise
    // propagation and association share one solve.)
    smoother_->update(propagation, newValues);
    propagation = FactorGraph();
    newValues = Values();
  }

  // 2. Candidates and weights, all against the marginal of the propagated estimate.
  std::optional<JointMarginal> marginal;
  if (!known && !landmarks_.empty() && !step.detections.empty()) {
    std::vector<Key> keys = {pose};
    for (const Landmark& landmark : landmarks_) keys.push_back(landmark.key);
    marginal = smoother_->jointMarginal(keys);
  }
  FactorGraph associations = propagation;
  Values values = newValues;
  const int landmarksBeforeStep = landmarks();
  std::vector<std::size_t> factorsOfRecord;  // how many of `associations` each of this step's records added
  const std::size_t first = records_.size();
  for (std::size_t i = 0; i < step.detections.size(); ++i) {
    DetectionRecord record;
    record.step = k;
    record.detection = static_cast<int>(i);
    record.measurement = step.detections[i];
    record.truth = step.detections[i].truthId;
    record.semanticLikelihoods = semanticLikelihoods(header_, step.detections[i]);
    records_.push_back(std::move(record));
  }
  const bool jointly = !known && options_.birth == BirthRule::Unassigned;
  if (jointly) {
    // (docs/association-front-end.md, §1-4): every candidate of the step against the marginal from before it,
    // then one joint assignment with the unassigned hypothesis.
    for (const Detection& detection : step.detections) unassigned_.observe(detection);
    for (std::size_t r = first; r < records_.size(); ++r) {
      findCandidatesWithUnassigned(marginal ? &*marginal : nullptr, landmarksBeforeStep, records_[r]);
    }
    assignJointly(first);
  }
  for (std::size_t r = first; r < records_.size(); ++r) {
    DetectionRecord& record = records_[r];
    const std::size_t factorsBefore = associations.size();
    const Value& robot = values.exists(pose) ? values.value(pose) : smoother_->estimate().value(pose);

    if (known) {
      if (record.truth && *record.truth != kNotALandmark) {
        const auto found = landmarkOfTruthId_.find(*record.truth);
        const int index = found != landmarkOfTruthId_.end()
                              ? found->second
                              : addLandmark(factory_.initialLandmark(record.measurement, robot), *record.truth, values);
        record.knownLandmark = index;
        associations.add(factory_.detectionFactor(pose, landmarks_[index].key, record.measurement));
        landmarks_[index].classBelief.update(record.semanticLikelihoods);
      }
    } else {
      if (!jointly && marginal) findCandidates(*marginal, landmarksBeforeStep, record);
      if (record.candidates.empty()) {
        const int index = addLandmark(factory_.initialLandmark(record.measurement, robot), std::nullopt, values);
        record.createdLandmark = index;
        associations.add(factory_.detectionFactor(pose, landmarks_[index].key, record.measurement));
        landmarks_[index].classBelief.update(record.semanticLikelihoods);
      } else {
        const std::vector<FactorPtr> factors = associationFactors(record);
        if (record.mixture && options_.warmStart) {
          // Warm start: this solve uses the most likely candidate under a Cauchy kernel (an outlier pulls little);
          // the mixture replaces it below.
          const int best = record.candidates[bestCandidate(record)];
          associations.add(factory_.detectionFactor(pose, landmarks_[best].key, record.measurement, 1.0,
                                                    std::make_shared<CauchyKernel>(kWarmStartCauchyScale)));
        } else {
          for (const FactorPtr& factor : factors) associations.add(factor);
        }
        for (std::size_t c = 0; c < record.candidates.size(); ++c) {
          landmarks_[record.candidates[c]].classBelief.update(record.semanticLikelihoods, record.weights[c]);
        }
      }
    }
    factorsOfRecord.push_back(associations.size() - factorsBefore);
  }

  // 4. Solve, and remember which smoother factors belong to which detection (they follow any propagation ones).
  const std::vector<FactorIndex> indices = smoother_->update(associations, values);
  std::size_t next = propagation.size();
  for (std::size_t i = 0; i < factorsOfRecord.size(); ++i) {
    DetectionRecord& record = records_[firstRecordOfStep_.back() + i];
    for (std::size_t c = 0; c < factorsOfRecord[i]; ++c) record.factors.push_back(indices.at(next++));
  }
  if (options_.warmStart) {
    bool switched = false;
    for (std::size_t r = firstRecordOfStep_.back(); r < records_.size(); ++r) {
      if (!records_[r].mixture) continue;
      smoother_->replaceFactor(records_[r].factors.at(0), records_[r].mixture);
      switched = true;
    }
    if (switched) smoother_->update();
  }
  if (options_.strategy == AssociationStrategy::Gpda && options_.emIterations > 0) {
    const int firstStep = std::max(0, k + 1 - options_.emWindow);
    expectationMaximization(firstRecordOfStep_[firstStep], options_.emIterations);
  }
}

LinearizedLikelihood SemanticSlam::geometricLikelihood(const JointMarginal& marginal, const Landmark& landmark,
                                                       const Detection& detection) const {
  const Key pose = poseKeys_.back();
  const std::vector<FactorPtr> factor = {factory_.detectionFactor(pose, landmark.key, detection)};
  return linearizedLikelihood(factor, smoother_->estimate(), marginal.restrictedTo({pose, landmark.key}));
}

void SemanticSlam::findCandidates(const JointMarginal& marginal, int landmarkCount, DetectionRecord& record) const {
  std::vector<double> logWeights;
  for (int j = 0; j < landmarkCount; ++j) {
    const Landmark& landmark = landmarks_[j];
    const LinearizedLikelihood geometric = geometricLikelihood(marginal, landmark, record.measurement);
    if (!gate_.accepts(geometric)) continue;
    const double semantic = landmark.classBelief.predictive(record.semanticLikelihoods);
    if (!(semantic > 0.0)) continue;  // a label this landmark's class belief rules out (exact model, p = 0)
    record.candidates.push_back(j);
    logWeights.push_back(geometric.logLikelihood + std::log(semantic));  // (B, sec. IV-B)
  }
  if (!record.candidates.empty()) record.weights = normalizeLogWeights(logWeights);
}

void SemanticSlam::findCandidatesWithUnassigned(const JointMarginal* marginal, int landmarkCount,
                                                DetectionRecord& record) const {
  // P₀(s): the label's predictive under the uniform class prior (1 without semantics). A label that every class
  // rules out (all likelihoods 0, e.g. an exact model) carries no usable information: it counts as uninformative
  // here, and every landmark's predictive of it is 0, so the detection is unassigned.
  double labelPrior = record.semanticLikelihoods.size() > 0 ? record.semanticLikelihoods.mean() : 1.0;
  if (!(labelPrior > 0.0) || !std::isfinite(labelPrior)) labelPrior = 1.0;
  record.unassignedLogLikelihood = unassigned_.logDensity(record.measurement) + std::log(labelPrior);  // (§1)
  if (!marginal) return;
  for (int j = 0; j < landmarkCount; ++j) {
    const Landmark& landmark = landmarks_[j];
    const double semantic = landmark.classBelief.predictive(record.semanticLikelihoods);
    if (!(semantic > 0.0)) continue;  // a label this landmark's class belief rules out
    const LinearizedLikelihood geometric = geometricLikelihood(*marginal, landmark, record.measurement);
    // The joint gate (§3): g = d² − 2 ln(P(s | j) / P₀(s)) against the χ²_m quantile.
    const double jointStatistic = geometric.innovationChi2 - 2.0 * std::log(semantic / labelPrior);
    if (jointStatistic > gate_.threshold(geometric.dimension)) continue;
    record.candidates.push_back(j);
    record.logLikelihoods.push_back(geometric.logLikelihood + std::log(semantic));
  }
  if (!record.candidates.empty()) record.weights = normalizeLogWeights(record.logLikelihoods);
}

void SemanticSlam::assignJointly(std::size_t first) {
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
                              record.weights[c] * (withNull ? 1.0 - options_.nullWeight : 1.0)});
      }
      if (withNull) {
        components.push_back({factory_.detectionFactor(pose, landmarks_[best].key, record.measurement,
                                                       options_.nullSigmaScale),
                              options_.nullWeight});
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

void SemanticSlam::finish() {
  if (options_.strategy == AssociationStrategy::Gpda) expectationMaximization(0, 10);
  smoother_->converge();
}

std::pair<std::optional<int>, double> SemanticSlam::chosenAssociation(const DetectionRecord& record) const {
  if (record.knownLandmark) return {*record.knownLandmark, 1.0};
  if (record.createdLandmark) return {*record.createdLandmark, 1.0};
  if (record.candidates.empty()) return {std::nullopt, 1.0};  // `known`: clutter, no factor
  if (record.mixture) {
    const auto& mixture = static_cast<const MaxMixtureFactor&>(*record.mixture);
    const int active = mixture.activeComponent(smoother_->estimate());
    if (active >= static_cast<int>(record.candidates.size())) return {std::nullopt, options_.nullWeight};
    const double scale = options_.strategy == AssociationStrategy::MaxMixtureNullHypothesis ? 1.0 - options_.nullWeight : 1.0;
    return {record.candidates[active], record.weights[active] * scale};
  }
  const int best = argmax(record.weights);  // ml: the one candidate left; gpda: the most probable after its EM
  return {record.candidates[best], record.weights[best]};
}

RunResult SemanticSlam::result(bool withPoseCovariances) const {
  RunResult result;
  result.method = strategyName(options_.strategy);
  if (options_.birth == BirthRule::Unassigned) result.method += "+unassigned";  // not the paper's birth rule
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
  for (int j = 0; j < landmarks(); ++j) {
    const bool hasClasses = header_.semantic != SemanticKind::None;
    result.landmarks.push_back({j, toLandmarkState(estimate.value(landmarks_[j].key)),
                                hasClasses ? landmarks_[j].classBelief.probabilities() : Vector()});
  }
  return result;
}

}  // namespace semslam
