#pragma once
// Relative pose error (RPE; Sturm et al. 2012, notation of the TUM RGB-D benchmark), as evo's metrics.RPE
// (evo/core/metrics.py) and the evo_rpe tool:
//
//   for each selected pair (i, j) (PairSelection.h) with reference poses Q and estimated poses P:
//     E_ij = (Q_i⁻¹ Q_j)⁻¹ (P_i⁻¹ P_j)          (evo's rpe_base; inverses as [Rᵀ, −Rᵀt])
//     e_ij = relation(E_ij)                       (PoseRelation.h; the default is ‖t(E_ij)‖₂, metres)
//
// Pairs come from the ESTIMATED trajectory unless pairsFromReference (evo's default and its
// --pairs_from_reference option). The estimate is used as given: align it first if wanted (evo_rpe does not
// align by default; alignment with scale changes the estimate's path length and so the pairs).

#include <vector>

#include "semslam/eval/PairSelection.h"
#include "semslam/eval/PoseRelation.h"
#include "semslam/models/Trajectory.h"

namespace semslam {

struct RelativePoseErrorOptions {
  PoseRelation relation = PoseRelation::TranslationPart;
  double delta = 1.0;                   ///< evo_rpe's -d (default 1)
  DeltaUnit unit = DeltaUnit::Frames;   ///< evo_rpe's -u (default frames)
  bool allPairs = false;                ///< evo_rpe's --all_pairs
  double relativeTolerance = 0.1;       ///< evo_rpe's -t (metres with allPairs only)
  bool pairsFromReference = false;      ///< evo_rpe's --pairs_from_reference
};

struct RelativePoseErrors {
  std::vector<PosePair> pairs;
  std::vector<double> errors;  ///< errors[k] belongs to pairs[k]
};

/// Throws InputError when the sizes differ or the options select no pair.
RelativePoseErrors relativePoseErrors(const Trajectory& reference, const Trajectory& estimate,
                                      const RelativePoseErrorOptions& options = {});

}  // namespace semslam
