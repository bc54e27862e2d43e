#pragma once
// VisibilityModel2 / VisibilityModel3: which objects a sensor can see (field of view and maximum range), and the
// object observation model P(β_k | x_k, X^o) of paper A (sec. IV-B, eq. 14-16).
//
// Visibility
//   With the point in the sensor frame p = (x · s)⁻¹ l (s = bodyToSensor) and r = ‖p‖, a point is visible iff
//       0 < r ≤ maxRange                         (maxRange = 0: unlimited)
//   and its angle off the sensor's x axis is at most half the field of view (fieldOfView = full angle; 0 or ≥ 2π:
//   all around, as in MeasurementLog's SensorSpec):
//       2D: |atan2(p_y, p_x)| ≤ fieldOfView / 2,
//       3D: atan2(‖(p_y, p_z)‖, p_x) ≤ fieldOfView / 2   (a circular cone about the x axis).
//   Both limits are inclusive; a point at the sensor itself (r = 0) is not visible.
//
// Object observation model (A, eq. 14-16; decision in docs/models.md)
//   β_k = (β_{k,1}, ..., β_{k,n}) assigns each of the n detections of step k to an object index in [0, N).
//   Paper A: "if the model predicts observation of all objects corresponding to β_k then P(β_k | x_k, X^o_{β_k})
//   is equal to a constant, otherwise it is zero", as in DA-BSP (Pathak et al.), where a hypothesis that needs an
//   object the sensor cannot see from x_k is impossible. Two forms are provided:
//     associationFeasible(x, X^o, β):  the paper's indicator — every β_{k,i} visible from x_k and, when
//         oneDetectionPerObject (default), no object assigned twice (an object produces at most one detection per
//         step). It depends on X^o_{β_k} only, so eq. 16 needs samples of x_k and X^o_{β_k} only; the constant is
//         irrelevant because component weights are normalised.
//     associationProbability(x, X^o, β):  the same support, normalised: uniform over the feasible assignments of
//         the n detections to the V objects visible from x_k,
//             P(β_k | x_k, X^o) = (V − n)! / V!   (one detection per object; 0 when n > V),
//             P(β_k | x_k, X^o) = 1 / V^n         (otherwise),
//         and 0 for an infeasible β_k. It sums to one over all β_k ∈ [0, N)^n whenever a feasible one exists, and
//         depends on every object's position (through V): a hypothesis is penalised where many objects are in view.
//   n = 0 (no detections) has the single, empty assignment: probability 1.
//   Clutter and new objects are outside paper A's model (N is known); an index outside [0, N) throws
//   std::invalid_argument.
//
// Invariants: fieldOfView and maxRange are finite and ≥ 0 (else std::invalid_argument).

#include <span>
#include <vector>

#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// The limits and the combinatorics shared by the 2D and 3D models.
class VisibilityLimits {
 public:
  /// fieldOfView: full angle in radians about the sensor's x axis (0: all around); maxRange: metres (0: unlimited).
  VisibilityLimits(double fieldOfView, double maxRange, bool oneDetectionPerObject);

  double fieldOfView() const { return fieldOfView_; }
  double maxRange() const { return maxRange_; }
  bool oneDetectionPerObject() const { return oneDetectionPerObject_; }

  /// Visibility of a point given its range r and its angle off the sensor's x axis (in [0, π]).
  bool visibleAt(double range, double angleOffAxis) const;

  /// 1 / (number of feasible assignments of `detections` detections to `visibleObjects` objects), 0 if none.
  double uniformAssociationProbability(int visibleObjects, int detections) const;

 protected:
  /// Throws unless every index of beta is in [0, objects); true when no object appears twice.
  static bool checkAssociation(std::span<const int> beta, std::size_t objects);

 private:
  double fieldOfView_;
  double maxRange_;
  bool oneDetectionPerObject_;
};

class VisibilityModel2 : public VisibilityLimits {
 public:
  explicit VisibilityModel2(double fieldOfView = 0.0, double maxRange = 0.0, const SE2& bodyToSensor = SE2(),
                            bool oneDetectionPerObject = true);
  /// From a log's sensor (its bodyToSensor must be an SE2).
  static VisibilityModel2 fromSpec(const SensorSpec& sensor, bool oneDetectionPerObject = true);

  const SE2& bodyToSensor() const { return bodyToSensor_; }

  /// Whether `landmark` (world frame) is visible from the robot pose.
  bool visible(const SE2& robot, const Point2& landmark) const;
  /// The indices of the visible objects, in increasing order.
  std::vector<int> visibleObjects(const SE2& robot, std::span<const Point2> objects) const;
  /// The paper's indicator: every assigned object visible (and, by default, none assigned twice).
  bool associationFeasible(const SE2& robot, std::span<const Point2> objects, std::span<const int> beta) const;
  /// Uniform over the feasible assignments to the visible objects, 0 if infeasible.
  double associationProbability(const SE2& robot, std::span<const Point2> objects, std::span<const int> beta) const;

 private:
  SE2 bodyToSensor_;
};

class VisibilityModel3 : public VisibilityLimits {
 public:
  explicit VisibilityModel3(double fieldOfView = 0.0, double maxRange = 0.0, const SE3& bodyToSensor = SE3(),
                            bool oneDetectionPerObject = true);
  /// From a log's sensor (its bodyToSensor must be an SE3).
  static VisibilityModel3 fromSpec(const SensorSpec& sensor, bool oneDetectionPerObject = true);

  const SE3& bodyToSensor() const { return bodyToSensor_; }

  bool visible(const SE3& robot, const Point3& landmark) const;
  std::vector<int> visibleObjects(const SE3& robot, std::span<const Point3> objects) const;
  bool associationFeasible(const SE3& robot, std::span<const Point3> objects, std::span<const int> beta) const;
  double associationProbability(const SE3& robot, std::span<const Point3> objects, std::span<const int> beta) const;

 private:
  SE3 bodyToSensor_;
};

}  // namespace semslam
