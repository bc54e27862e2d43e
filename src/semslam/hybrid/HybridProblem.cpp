#include "semslam/hybrid/HybridProblem.h"

#include <cmath>
#include <limits>

#include "semslam/association/ClassBelief.h"
#include "semslam/factors/ViewpointSemanticFactor.h"
#include "semslam/hybrid/CartesianGateFactor.h"
#include "semslam/core/InputError.h"
#include "semslam/models/ClassifierFactory.h"

namespace semslam {
namespace {

const LogHeader& checked(const LogHeader& header) {
  if (header.dimension != 2 && header.dimension != 3) throw InputError("hybrid belief: the log must be 2D or 3D");
  if (!header.initialPose) throw InputError(
        "hybrid belief: the log has no initial pose prior, which holds the first pose (the hybrid belief's weights "
        "need a proper prior): add \"initial_pose\": {\"mean\", \"covariance\"} to the "
        "log's header line (docs/measurement-log.md)");
  if (header.landmarkPriors.empty()) {
    throw InputError("hybrid belief: the log has no landmark priors (paper A needs the known, uncertain map; "
                     "convert with --map-prior)");
  }
  return header;
}

}  // namespace

HybridProblem::HybridProblem(const LogHeader& header, bool useSemantics)
    : header_(checked(header)), factory_(header_) {
  if (header_.dimension == 2) visibility_ = VisibilityModel2::fromSpec(header_.sensor);
  else visibility_ = VisibilityModel3::fromSpec(header_.sensor);
  if (!useSemantics || header_.semantic == SemanticKind::None) return;
  switch (header_.classifier.kind) {
    case ClassifierModelSpec::Kind::ViewpointGaussian:
      if (!header_.landmarksHavePose) {
        throw InputError("hybrid belief: the viewpoint classifier model needs objects with a pose");
      }
      if (header_.semantic != SemanticKind::Scores && header_.semantic != SemanticKind::Probabilities) {
        throw InputError("hybrid belief: the viewpoint classifier model needs class vectors (scores)");
      }
      viewpointModel_ = makeViewpointClassifier(header_.classifier, header_.classes);
      semantic_ = SemanticModelKind::Viewpoint;
      break;
    case ClassifierModelSpec::Kind::Categorical: semantic_ = SemanticModelKind::Categorical; break;
    case ClassifierModelSpec::Kind::None: break;
  }
}

Key HybridProblem::objectKey(int object) { return landmarkKey(static_cast<std::uint64_t>(object)); }

// P(x_0) Π_i P(x^o_i) (A, eq. 3); the class prior P(c_i) is a log-constant of the candidates.
void HybridProblem::priors(FactorGraph& factors, Values& values) const {
  factors.add(factory_.posePriorFactor(poseKey(0), *header_.initialPose));
  values.insert(poseKey(0), factory_.initialPose(header_));
  for (int j = 0; j < objects(); ++j) {
    factors.add(factory_.landmarkPriorFactor(objectKey(j), header_.landmarkPriors[j]));
    values.insert(objectKey(j), factory_.landmarkValue(header_.landmarkPriors[j].mean));
  }
}

std::vector<FactorPtr> HybridProblem::detectionFactors(Key pose, int object, const Detection& detection,
                                                       int classIndex) const {
  // P(z_geo | x_k, x^o) · P(z_sem | x_k, x^o, c) (A, eq. 10); the semantic part by the viewpoint model (A, eq. 2, 18).
  std::vector<FactorPtr> factors{factory_.detectionFactor(pose, objectKey(object), detection)};
  if (semantic_ == SemanticModelKind::Viewpoint) {
    if (!detection.classVector) throw InputError("hybrid belief: a detection has no class scores");
    if (header_.dimension == 2) {
      factors.push_back(std::make_shared<const ViewpointSemanticFactor<SE2>>(
          pose, objectKey(object), *detection.classVector, classIndex, viewpointModel_,
          std::get<SE2>(header_.sensor.bodyToSensor)));
    } else {
      factors.push_back(std::make_shared<const ViewpointSemanticFactor<SE3>>(
          pose, objectKey(object), *detection.classVector, classIndex, viewpointModel_,
          std::get<SE3>(header_.sensor.bodyToSensor)));
    }
  }
  return factors;
}

FactorPtr HybridProblem::gateFactor(Key pose, int object, const Detection& detection) const {
  FactorPtr factor = factory_.detectionFactor(pose, objectKey(object), detection);  // validates the detection
  const Key l = objectKey(object);
  const bool posed = header_.landmarksHavePose;
  if (header_.sensor.kind == SensorKind::RangeBearing) {
    const Vector2 rb = detection.geometry;
    const Matrix2 covariance = detection.covariance;
    const SE2& mount = std::get<SE2>(header_.sensor.bodyToSensor);
    if (posed) return CartesianGateFactor<SE2>::fromRangeBearing(pose, l, rb, covariance, mount);
    return CartesianGateFactor<Point2>::fromRangeBearing(pose, l, rb, covariance, mount);
  }
  if (header_.sensor.kind == SensorKind::RangeBearingElevation) {
    const Vector3 rbe = detection.geometry;
    const Matrix3 covariance = detection.covariance;
    const SE3& mount = std::get<SE3>(header_.sensor.bodyToSensor);
    if (posed) return CartesianGateFactor<SE3>::fromRangeBearingElevation(pose, l, rbe, covariance, mount);
    return CartesianGateFactor<Point3>::fromRangeBearingElevation(pose, l, rbe, covariance, mount);
  }
  return factor;  // relative position or pose: linear in the positions already
}

bool HybridProblem::visible(const Value& robot, const Vector& position) const {
  if (const auto* model = std::get_if<VisibilityModel2>(&visibility_)) {
    return model->visible(std::get<SE2>(robot), Point2(position(0), position(1)));
  }
  return std::get<VisibilityModel3>(visibility_).visible(std::get<SE3>(robot),
                                                         Point3(position(0), position(1), position(2)));
}

bool HybridProblem::associationFeasible(const Value& robot, const std::vector<Vector>& positions,
                                        const std::vector<int>& beta) const {
  if (const auto* model = std::get_if<VisibilityModel2>(&visibility_)) {
    std::vector<Point2> points;
    for (const Vector& p : positions) points.emplace_back(p(0), p(1));
    return model->associationFeasible(std::get<SE2>(robot), points, beta);
  }
  std::vector<Point3> points;
  for (const Vector& p : positions) points.emplace_back(p(0), p(1), p(2));
  return std::get<VisibilityModel3>(visibility_).associationFeasible(std::get<SE3>(robot), points, beta);
}

double HybridProblem::semanticLogConstant(const Detection& detection, int classIndex) const {
  if (semantic_ != SemanticModelKind::Categorical) return 0.0;
  const Vector likelihoods = semanticLikelihoods(header_, detection);
  const double p = likelihoods(classIndex);
  return p > 0.0 ? std::log(p) : -std::numeric_limits<double>::infinity();
}

}  // namespace semslam
