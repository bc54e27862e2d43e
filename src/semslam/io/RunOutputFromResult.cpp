#include "semslam/io/RunOutputFromResult.h"

#include <stdexcept>

#include "semslam/eval/LandmarkMetrics.h"

namespace semslam {

RunOutput runOutputFrom(const MeasurementLog& log, const RunResult& result,
                        std::vector<AssociationRecord> associations,
                        const std::vector<std::optional<Matrix>>& landmarkCovariances) {
  if (result.poses.size() > log.steps.size()) throw std::invalid_argument("more poses than log steps");
  RunOutput output;
  output.dimension = log.header.dimension;
  const int d = log.header.dimension;
  std::vector<double> times, trueTimes;
  std::vector<SE3> poses, truePoses;
  for (std::size_t k = 0; k < result.poses.size(); ++k) {
    times.push_back(log.steps[k].time);
    poses.push_back(toSE3(result.poses[k]));
    if (log.steps[k].truePose) {
      trueTimes.push_back(log.steps[k].time);
      truePoses.push_back(toSE3(*log.steps[k].truePose));
    }
  }
  output.trajectory = Trajectory(times, poses);
  // The truth wherever the log has it: a log with true poses on some steps only still gets them, at their times.
  if (!truePoses.empty()) output.truth = Trajectory(trueTimes, truePoses);
  for (const Matrix& covariance : result.poseCovariances) {
    output.posePositionCovariances.push_back(covariance.topLeftCorner(d, d));
  }
  for (std::size_t j = 0; j < result.landmarks.size(); ++j) {
    const EstimatedLandmark& estimated = result.landmarks[j];
    RunLandmark landmark;
    landmark.id = estimated.id;
    landmark.position = landmarkPosition(estimated.state);
    if (estimated.classProbabilities.size() > 0) {
      Eigen::Index best = 0;
      landmark.classProbability = estimated.classProbabilities.maxCoeff(&best);
      landmark.classIndex = static_cast<int>(best);
    }
    if (j < landmarkCovariances.size() && landmarkCovariances[j]) {
      landmark.positionCovariance = landmarkCovariances[j]->topLeftCorner(d, d);
    }
    output.landmarks.push_back(std::move(landmark));
  }
  output.landmarkTruth = log.header.landmarkTruth;
  output.associations = std::move(associations);
  return output;
}

}  // namespace semslam
