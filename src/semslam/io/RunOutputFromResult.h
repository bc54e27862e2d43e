#pragma once
// Building a run folder's contents (RunFolder.h) from what a method reports (models/RunResult.h)
// and the log it ran on: every method writes its folder through this one function.
//
//   trajectory      result.poses with the steps' times;  truth: the true poses of the steps that have one, at their times;
//   covariances     the position block (top-left d × d, translation first) of each result.poseCovariances entry;
//   landmarks       result.landmarks: the most probable class and its probability (-1 without a class belief),
//                   with `landmarkCovariances` (by landmark index, position block) where given;
//   associations    the caller's records (a method knows the weights behind its choices).

#include <optional>
#include <vector>

#include "semslam/eval/RunEvaluation.h"
#include "semslam/io/RunFolder.h"

namespace semslam {

RunOutput runOutputFrom(const MeasurementLog& log, const RunResult& result,
                        std::vector<AssociationRecord> associations,
                        const std::vector<std::optional<Matrix>>& landmarkCovariances = {});

}  // namespace semslam
