#pragma once
// LandmarkLifecycle: whether each landmark of a map is provisional, confirmed or gone, by the M-of-N rule of
// docs/association-front-end.md §5. It decides; the caller edits the graph.
//
// A landmark starts either
//   confirmed    (a map prior, a landmark of known association, every landmark under paper B's threshold birth
//                rule), or
//   provisional  (born from a detection that the joint assignment left unassigned: a new landmark or clutter,
//                which one step cannot tell apart).
// A provisional landmark becomes
//   confirmed  once M = `confirmations` detections assigned to it, its birth detection included, are each at
//              least Δt = `spacingSeconds` after the previous one counted (a static object is seen again later;
//              something passing through, or a burst, is not; seconds, not keyframes, so that the rule means the
//              same at every keyframe rate), and made
//              from a robot position at least D from the previous counted one's, D = max(`viewpointDistance`,
//              `viewpointSigmas` × σ_p), σ_p the sighting's own position error (MeasurementFactory::
//              detectionPositionSigma): an observer standing still sees the same view, with the same error, again;
//              one that has moved by more than the detection's error sees it from elsewhere (0 and 0: any);
//   dropped    once it has been inside the sensor's field on N = `patience` steps after its birth without being
//              confirmed (it should have been seen again);
//   merged     into another landmark, when the caller's test (§5) says the two are one.
// A confirmed landmark can still be merged into another (a duplicate: the same object mapped twice, e.g. once
// before and once after a stretch of drift, §5c), when the caller's test says the two are one.
//
// Invariants: indices are dense and 0-based, in the order of add*(); states move only Provisional → Confirmed,
// Provisional → Dropped, Provisional → Merged, Confirmed → Merged; every counter refers to steps after the
// landmark's birth.

#include <optional>
#include <vector>

#include "semslam/geometry/Matrix.h"

namespace semslam {

/// The M-of-N rule's numbers (docs/association-front-end.md §5 says where they come from).
struct ProvisionalLandmarkRule {
  int confirmations = 2;        ///< M
  double spacingSeconds = 1.0;  ///< Δt, in the log's time unit (seconds)
  int patience = 10;            ///< N: in-field steps without confirmation before a drop
  double viewpointDistance = 0.0;  ///< metres the robot must have moved since the last counted sighting (0: any)
  double viewpointSigmas = 0.0;    ///< the same in units of the sighting's position error σ_p (0: any)
};

class LandmarkLifecycle {
 public:
  enum class State { Provisional, Confirmed, Dropped, Merged };
  using Rule = ProvisionalLandmarkRule;

  /// Throws std::invalid_argument for M < 1, N < 1, or a negative or non-finite spacing or viewpoint distance.
  explicit LandmarkLifecycle(Rule rule = {});

  const Rule& rule() const { return rule_; }

  /// A new landmark; returns its index.
  int addConfirmed();
  int addProvisional(double birthTime, const Vector& birthRobotPosition = Vector());

  State state(int landmark) const { return landmarks_.at(static_cast<std::size_t>(landmark)).state; }
  bool provisional(int landmark) const { return state(landmark) == State::Provisional; }
  /// Provisional or confirmed: a landmark of the map that detections may be assigned to.
  bool active(int landmark) const;
  /// The landmark a merged one went into (followed to the end of a chain of merges); nullopt if not merged.
  std::optional<int> mergedInto(int landmark) const;
  int size() const { return static_cast<int>(landmarks_.size()); }

  /// A detection at `time`, made from `robotPosition`, with position error `positionSigma` (metres), assigned to
  /// `landmark`. Returns true when this confirms a provisional landmark.
  bool observe(int landmark, double time, const Vector& robotPosition = Vector(), double positionSigma = 0.0);
  /// A step after its birth at which provisional `landmark` was inside the sensor's field. Returns true when the
  /// landmark has now used up its patience unconfirmed: the caller must drop it.
  bool passedInField(int landmark);

  void drop(int landmark);
  /// A provisional or confirmed `landmark` into another active one.
  void merge(int landmark, int into);

 private:
  struct Entry {
    State state = State::Confirmed;
    int counted = 0;             // detections counted towards M
    double lastCountedTime = 0;  // time of the last counted one
    Vector lastCountedPosition;  // the robot's position then
    int inFieldSteps = 0;
    int mergedInto = -1;
  };
  Entry& provisionalEntry(int landmark);

  Rule rule_;
  std::vector<Entry> landmarks_;
};

}  // namespace semslam
