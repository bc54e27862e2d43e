#pragma once
// MixtureChoiceCache: each detection's last max-mixture choice, kept with how far it holds, so that asking again
// which component a detection's mixture uses costs a bound instead of an evaluation (docs/association-front-end.md
// §6b, "The reach of a choice"). The front end asks it, at every step, for every detection of every landmark seen.
//
// A choice made at an estimate (MaxMixtureFactor::chooseAt) holds while the landmark seen from the robot,
// p = x⁻¹ · l, has moved by less than its reach; the move is bounded from the variables alone (factors/
// SeenPointMove.h). Beyond it, or for a mixture without a reach (components on several landmarks, a sensor without
// a bound), the choice is made anew.
//
// Invariant: every answer is MaxMixtureFactor::activeComponent at the estimate asked about. An entry is kept per
// detection together with the mixture it was made for, held, so that a replaced mixture (a re-weighting, a merge)
// can never share its address and is always chosen anew.

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "semslam/factors/MaxMixtureFactor.h"

namespace semslam {

class MixtureChoiceCache {
 public:
  /// A landmark's key and its value in the estimate, looked up once by a caller that asks for all its detections.
  using KnownValue = std::pair<Key, const Value*>;

  /// The component `mixture` (a MaxMixtureFactor) uses at `estimate`, for the detection numbered `detection`.
  int activeComponent(std::size_t detection, const FactorPtr& mixture, const Values& estimate,
                      const KnownValue* landmark = nullptr);

  /// How many answers needed a choice made anew (an evaluation of the mixture).
  std::size_t choicesMade() const { return choicesMade_; }

 private:
  struct Entry {
    FactorPtr mixture;
    int component = 0;
    double reach = 0.0;
    Key poseKey = 0;  // the mixture's keys, and their values where the choice was made (set where reach > 0)
    Key landmarkKey = 0;
    Value pose = Point2(0.0, 0.0);
    Value landmark = Point2(0.0, 0.0);
  };
  std::vector<std::optional<Entry>> entries_;
  std::size_t choicesMade_ = 0;
};

}  // namespace semslam
