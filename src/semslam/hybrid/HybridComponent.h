#pragma once
// HybridComponent: one term w^C_β1:k · b[X_k]^C_β1:k of the hybrid belief (A, eq. 5).
//
//   weight     w^C_β1:k = P(C, β_1:k | H_k), normalised over the belief's components;
//   history    β_1:k: per step, per detection, the log id of the object it is associated with; −1 marks a
//              detection that one-detection-at-a-time branching had to drop (no object jointly compatible).
//              Shared with every component of the same past (models/AssociationHistory.h): equal histories
//              are the same nodes, so a step costs O(1) per component whatever k;
//   ancestor   the index of the component of step k − 1 this one branched from (−1 at the first step); with
//              β_k, what hypotheses.jsonl writes per step, so a history is written once, not once per step;
//   classes    the class realization restricted to the objects associated so far (A sec. IV-D, collapsing):
//              classes[j] ∈ [0, M) for an associated object, −1 for one not yet associated (its class is not
//              enumerated: with the uniform prior every value gives the same weight and belief). Empty in the
//              geometric-only mode.
//   smoother   the Gaussian smoothing belief over every robot pose and object pose (eq. 9-11), a factor graph
//              with priors, motion, geometric and semantic factors. Shared and immutable: branching forks it
//              (Smoother::fork shares every factor) and updates the fork, so copying a component copies a pointer.

#include <memory>
#include <vector>

#include "semslam/models/HypothesisComponent.h"
#include "semslam/solve/Smoother.h"

namespace semslam {

struct HybridComponent {
  double weight = 1.0;
  AssociationHistory history;
  int ancestor = -1;
  std::vector<int> classes;
  std::shared_ptr<const Smoother> smoother;
};

}  // namespace semslam
