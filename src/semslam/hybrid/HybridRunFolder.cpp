#include "semslam/hybrid/HybridRunFolder.h"

#include <filesystem>

#include "semslam/hybrid/HypothesesJsonl.h"
#include "semslam/io/RunFolder.h"

namespace semslam {

RunMetrics writeHybridRunFolder(const std::string& directory, const MeasurementLog& log, const HybridRunOutput& run) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path dir(directory);
  const RunEvaluation evaluation = evaluateRun(log, run.result);
  writeRunMetrics((dir / "metrics.json").string(), evaluation.metrics);

  RunOutput folder;
  folder.dimension = 2;
  std::vector<double> times;
  std::vector<SE3> estimated, truth;
  bool allTrue = true;
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    times.push_back(log.steps[k].time);
    estimated.push_back(toSE3(run.result.poses[k]));
    if (log.steps[k].truePose) truth.push_back(toSE3(*log.steps[k].truePose));
    else allTrue = false;
    folder.posePositionCovariances.push_back(run.result.poseCovariances[k].topLeftCorner(2, 2));
  }
  folder.trajectory = Trajectory(times, estimated);
  if (allTrue && !truth.empty()) folder.truth = Trajectory(times, truth);
  for (const EstimatedLandmark& l : run.result.landmarks) {
    RunLandmark row;
    row.id = l.id;
    row.position = std::visit(
        [](const auto& v) -> Vector {
          using V = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<V, SE2> || std::is_same_v<V, SE3>) return v.translation();
          else return v;
        },
        l.state);
    if (l.classProbabilities.size() > 0) {
      Eigen::Index best = 0;
      row.classProbability = l.classProbabilities.maxCoeff(&best);
      row.classIndex = static_cast<int>(best);
    }
    folder.landmarks.push_back(row);
  }
  folder.landmarkTruth = log.header.landmarkTruth;
  // The association marginal (eq. 8) of the heaviest component's history.
  double historyWeight = 1.0;
  if (!run.steps.empty() && !run.result.components.empty()) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < run.result.components.size(); ++i) {
      if (run.result.components[i].weight > run.result.components[best].weight) best = i;
    }
    for (const AssociationHypothesis& a : run.steps.back().marginals.association) {
      if (a.associations == run.result.components[best].associations) historyWeight = a.weight;
    }
  }
  for (std::size_t k = 0; k < run.result.associations.size(); ++k) {
    for (std::size_t i = 0; i < run.result.associations[k].size(); ++i) {
      AssociationRecord record;
      record.step = static_cast<int>(k);
      record.detection = static_cast<int>(i);
      record.landmark = run.result.associations[k][i];
      record.weight = historyWeight;
      record.truth = log.steps[k].detections[i].truthId;
      folder.associations.push_back(record);
    }
  }
  writeRunFolder(directory, folder);
  writeHypothesesJsonl((dir / "hypotheses.jsonl").string(), run.steps);
  return evaluation.metrics;
}

}  // namespace semslam
