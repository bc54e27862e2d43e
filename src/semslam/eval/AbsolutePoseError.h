#pragma once
// Absolute pose error (APE; the ATE of Sturm et al. when the relation is the translation part), as evo's
// metrics.APE (evo/core/metrics.py) and the evo_ape tool:
//
//   for each associated (and, if asked, aligned) pose pair with estimate P_i and reference Q_i:
//     trans_part:       e_i = ‖t(P_i) − t(Q_i)‖₂                     (evo compares positions directly)
//     other relations:  e_i = relation(E_i),  E_i = P_i⁻¹ Q_i        (evo's ape_base: relative_se3(est, ref))
//
// The poses correspond by index: associate and align first (see TrajectoryEvaluation.h for the whole pipeline).

#include <vector>

#include "semslam/eval/PoseRelation.h"
#include "semslam/models/Trajectory.h"

namespace semslam {

/// One error per pose pair; throws InputError when the sizes differ.
std::vector<double> absolutePoseErrors(const Trajectory& reference, const Trajectory& estimate,
                                       PoseRelation relation = PoseRelation::TranslationPart);

}  // namespace semslam
