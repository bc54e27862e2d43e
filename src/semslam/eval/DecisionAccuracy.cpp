#include "semslam/eval/DecisionAccuracy.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace semslam {

DecisionAccuracy evaluateDecisions(const std::vector<ScoredDecision>& decisions) {
  DecisionAccuracy accuracy;
  for (const ScoredDecision& scored : decisions) {
    const HistoryDecision& d = scored.decision;
    if (scored.truth == kNotALandmark) {
      if (d.right) throw std::invalid_argument("a clutter detection has no right landmark");
      ++accuracy.clutterTotal;
      if (!d.decided) ++accuracy.clutterRejected;
      continue;
    }
    if (scored.truth < 0) {
      throw std::invalid_argument("decision accuracy: truth " + std::to_string(scored.truth) +
                                  " is neither a landmark id nor clutter");
    }
    ++accuracy.realTotal;
    if (d.decided == d.right) {
      ++accuracy.realCorrect;
    } else if (!d.right) {
      ++accuracy.firstSightingsForced;
    } else if (d.decided) {
      ++accuracy.resightingsElsewhere;
    } else {
      ++accuracy.resightingsUnassigned;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  accuracy.accuracyReal = accuracy.realTotal > 0 ? static_cast<double>(accuracy.realCorrect) /
                                                       static_cast<double>(accuracy.realTotal)
                                                 : nan;
  accuracy.clutterRejectedFraction = accuracy.clutterTotal > 0 ? static_cast<double>(accuracy.clutterRejected) /
                                                                     static_cast<double>(accuracy.clutterTotal)
                                                               : nan;
  return accuracy;
}

}  // namespace semslam
