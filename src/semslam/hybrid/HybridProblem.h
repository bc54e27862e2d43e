#pragma once
// HybridProblem: what paper A's hybrid belief needs to know about a measurement log, read once from its header:
// the N objects of the known but uncertain map (A sec. III: "the number of objects is known"; their priors,
// eq. 3), the first pose's prior, the classifier model, the visibility model, and the factors of one
// detection associated with one object under one class hypothesis (eq. 10).
//
// Variables: robot pose x_k is poseKey(k); object j (the j-th landmark prior of the header, 0 ≤ j < N) is
// landmarkKey(j); objectId(j) is its id in the log.
//
// Semantic part of a detection (eq. 10), by the log's classifier model:
//   ViewpointGaussian  a ViewpointSemanticFactor (A eq. 2, 18) between x_k and the object (objects must have a
//                      pose); it enters both the weight integral and the component's smoother;
//   Categorical        P(z | c) from the confusion model (association/ClassBelief.h's semanticLikelihoods): it
//                      does not depend on continuous variables, so it multiplies the weight and adds no factor;
//   None, or useSemantics = false: nothing.
// Class prior (eq. 3): uniform, P(c_j) = 1/M.
//
// Dimension: 2D logs (SE2 poses; range-bearing, relative-position or relative-pose detections) and 3D logs (SE3
// poses; range-bearing-elevation, relative-position or relative-pose detections). In 3D the viewpoint classifier's
// angle is about the object's vertical axis (models/Viewpoint.h), as for paper A's mirror-symmetric car, and the
// visibility model is VisibilityModel3 (a cone about the sensor's x axis). A 3D log of a level world (z, roll and
// pitch fixed by tight priors and odometry) gives the 2D belief (tested).
//
// Limits (InputError): the header must have an initial pose prior and at least one landmark prior.

#include <memory>
#include <variant>
#include <vector>

#include "semslam/association/MeasurementFactory.h"
#include "semslam/graph/Factor.h"
#include "semslam/graph/FactorGraph.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/models/ViewpointClassifierModel.h"
#include "semslam/models/VisibilityModel.h"

namespace semslam {

enum class SemanticModelKind { None, Viewpoint, Categorical };

class HybridProblem {
 public:
  /// `useSemantics` false: the geometric-only problem (no semantic factor or likelihood, no classes).
  HybridProblem(const LogHeader& header, bool useSemantics);

  const LogHeader& header() const { return header_; }
  const MeasurementFactory& factory() const { return factory_; }
  int objects() const { return static_cast<int>(header_.landmarkPriors.size()); }
  int objectId(int object) const { return header_.landmarkPriors[object].id; }
  int classes() const { return header_.classes; }
  SemanticModelKind semantic() const { return semantic_; }
  /// Whether components carry a class realization (semantics in use).
  bool enumeratesClasses() const { return semantic_ != SemanticModelKind::None; }
  /// Whether an object at `position` (world frame, 2 or 3 entries) is in the sensor's view from `robot` (A, eq. 14).
  bool visible(const Value& robot, const Vector& position) const;
  /// The object observation model's indicator (A, eq. 14-16): every object of `beta` (indices into `positions`)
  /// visible from `robot`, none twice (VisibilityModel.h, associationFeasible).
  bool associationFeasible(const Value& robot, const std::vector<Vector>& positions,
                           const std::vector<int>& beta) const;

  static Key objectKey(int object);

  /// The prior factors and initial values of x_0 and every object (eq. 3).
  void priors(FactorGraph& factors, Values& values) const;

  /// The factors of `detection` associated with `object` under class `classIndex` (ignored without semantics):
  /// the geometric factor, and the viewpoint semantic factor when that model is in use.
  std::vector<FactorPtr> detectionFactors(Key pose, int object, const Detection& detection, int classIndex) const;
  /// The geometric factor the gate linearises (PropWeights.h): for a range-bearing sensor the detection in
  /// Cartesian form (CartesianGateFactor.h), otherwise the geometric factor itself.
  FactorPtr gateFactor(Key pose, int object, const Detection& detection) const;
  /// log P(z_sem | c) for the categorical model, 0 otherwise.
  double semanticLogConstant(const Detection& detection, int classIndex) const;

 private:
  LogHeader header_;
  MeasurementFactory factory_;
  SemanticModelKind semantic_ = SemanticModelKind::None;
  std::shared_ptr<const ViewpointClassifierModel> viewpointModel_;
  std::variant<VisibilityModel2, VisibilityModel3> visibility_;
};

}  // namespace semslam
