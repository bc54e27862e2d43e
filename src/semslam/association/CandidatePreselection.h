#pragma once
// CandidatePreselection: which mapped landmarks a step's detections can associate with, found through a grid over
// the landmark position estimates instead of a test of every landmark (docs/association-front-end.md, §7), so
// that a step's association costs what the landmarks near the robot cost, not what the map costs.
//
// Per step, select():
//   1. tracks the landmarks new since the last step: position from the estimate, spread σ_l from the landmark's
//      own marginal (the first one after its creation; 0 for one already inactive, which is never returned);
//   2. synchronises the grid with the estimate: one walk over the estimate in key order, comparing each tracked
//      landmark's position bit for bit with the grid's and re-binning those that moved (LandmarkGrid.h);
//   3. takes the newest pose's marginal (σ_t, σ_φ) and, per detection, the ball of PreselectionRadius.h under the
//      gate's χ²_m quantile (plus semanticGateAllowance for the joint gate); returns the union of the active
//      landmarks inside, ascending — or every active landmark when some detection has no finite ball.
// refresh() then stores the spreads of the selected landmarks from the step's joint marginal.
//
// The spread bound. In a linear-Gaussian model adding factors never increases a marginal covariance, so the last
// computed covariance of a landmark bounds every later one. Two things break that here: relinearisation and
// factors that lose information (a max-mixture switching to its broad null component, an EM re-weighting). The
// stored spread is therefore kSpreadSafety × √λmax of the last computed position block, refreshed every time the
// landmark is pre-selected (then it is in the step's joint marginal anyway, at no extra cost). §7 discusses it.
//
// Invariants: landmark indices are dense and 0-based (SemanticSlam's); the grid tracks indices 0..tracked−1 at the
// positions of the estimate select() last read; same inputs, same output (no hashing order reaches the result).

#include <functional>
#include <optional>
#include <vector>

#include "semslam/association/AssociationGate.h"
#include "semslam/association/LandmarkGrid.h"
#include "semslam/association/MeasurementFactory.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/solve/Smoother.h"

namespace semslam {

class CandidatePreselection {
 public:
  /// Multiplies √λmax of a landmark's last computed position covariance (see above).
  static constexpr double kSpreadSafety = 1.5;

  CandidatePreselection(const LogHeader& header, const AssociationGate& gate);

  /// The landmarks among 0..landmarkCount−1 (landmark j has variable keyOf(j), asked once) that are active and can
  /// pass the gate for some detection seen from `pose`, ascending. jointGate: the joint geometric × semantic gate of
  /// BirthRule::Unassigned. A landmark that is not active (dropped or merged: for good, its variable unconstrained)
  /// is never returned and its marginal never asked for.
  std::vector<int> select(const Smoother& smoother, Key pose, const std::vector<Detection>& detections,
                          bool jointGate, int landmarkCount, const std::function<Key(int)>& keyOf,
                          const std::function<bool(int)>& active);

  /// Stores the spreads of `landmarks` from a joint marginal that holds each of them.
  void refresh(const JointMarginal& marginal, const std::vector<int>& landmarks);

  int tracked() const { return grid_.size(); }
  /// Landmark j's spread bound σ_l (kSpreadSafety × √λmax of its last computed position covariance, see above), or
  /// none for a landmark not tracked yet (created since the last select()).
  std::optional<double> spread(int landmark) const {
    if (landmark < 0 || landmark >= grid_.size()) return std::nullopt;
    return grid_.spread(landmark);
  }
  double cellSize() const { return grid_.cellSize(); }

 private:
  void trackNew(const Smoother& smoother, int landmarkCount, const std::function<Key(int)>& keyOf,
                const std::function<bool(int)>& active);
  void synchronise(const Values& estimate);
  /// Re-bins the grid when the step's typical query radius left [h/4, 4h].
  void adaptCellSize(double typicalRadius);

  LogHeader header_;  // without the map priors and truth (the labels' likelihoods need the classifier only)
  MeasurementFactory factory_;
  AssociationGate gate_;
  LandmarkGrid grid_;
  std::vector<Key> keys_;  // of the tracked landmarks
  bool keysAscending_ = true;
  double spreadSum_ = 0.0;
};

}  // namespace semslam
