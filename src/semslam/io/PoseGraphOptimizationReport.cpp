#include "semslam/io/PoseGraphOptimizationReport.h"

#include <nlohmann/json.hpp>

#include "semslam/core/Version.h"
#include "semslam/io/AtomicFile.h"

namespace semslam {

namespace {

nlohmann::json matrixToJson(const Matrix& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

void addMarginals(const JointMarginal& joint, nlohmann::json& report) {
  nlohmann::json perKey = nlohmann::json::object();
  nlohmann::json keyNames = nlohmann::json::array();
  for (Key key : joint.keys()) {
    perKey[keyToString(key)] = matrixToJson(joint.at(key));
    keyNames.push_back(keyToString(key));
  }
  report["marginals"] = perKey;
  report["joint_marginal"] = {{"keys", keyNames}, {"matrix", matrixToJson(joint.covariance())}};
}

void addReplay(const PoseGraphReplayStatistics& replay, const OptimizationResult& convergence, nlohmann::json& report) {
  report["steps"] = replay.steps;
  report["replay_time_s"] = replay.replaySeconds;
  report["worst_step_time_s"] = replay.worstStepSeconds;
  report["worst_step"] = replay.worstStep;
  report["final_convergence"] = replay.finalConvergence;
  report["final_convergence_time_s"] = replay.finalConvergenceSeconds;
  report["final_convergence_iterations"] = convergence.iterations;
  report["relinearize_threshold"] = replay.params.relinearizeThreshold;
  report["relinearize_skip"] = replay.params.relinearizeSkip;
  report["wildfire_threshold"] = replay.params.wildfireThreshold;
  report["mean_reeliminated_variables"] = replay.meanReeliminatedVariables;
  report["mean_relinearized_variables"] = replay.meanRelinearizedVariables;
  report["mean_solved_cliques"] = replay.meanSolvedCliques;
  report["full_reorderings"] = replay.fullReorderings;
  report["cliques"] = replay.cliques;
  report["factor_entries"] = replay.factorEntries;
}

void addBatch(const OptimizationResult& result, nlohmann::json& report) {
  report["iterations"] = result.iterations;
  report["converged"] = result.converged;
  report["stop_reason"] = result.stopReason;
  report["initial_gradient_norm"] = result.initialGradientNorm;
  report["final_gradient_norm"] = result.finalGradientNorm;
}

}  // namespace

std::string poseGraphReportJson(const PoseGraphOptimizationReport& report) {
  nlohmann::json json;
  json["file"] = report.file;
  json["format"] = report.format;
  json["solver"] = report.solver;
  json["variables"] = report.variables;
  json["edges"] = report.edges;
  json["initial_chi2"] = report.initialChi2;
  json["final_chi2"] = report.finalChi2;
  json["time_s"] = report.seconds;
  json["version"] = std::string(version());
  if (report.replay) {
    addReplay(*report.replay, report.result, json);
  } else {
    addBatch(report.result, json);
  }
  if (report.marginals) addMarginals(*report.marginals, json);
  return json.dump(2) + "\n";
}

void writePoseGraphReport(const std::string& path, const PoseGraphOptimizationReport& report) {
  const std::string text = poseGraphReportJson(report);
  writeFileAtomically(path, [&text](std::ostream& out) { out << text; });
}

void writeReplayStepTimes(const std::string& path, const std::vector<double>& stepSeconds) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "step,seconds\n";
    for (std::size_t k = 0; k < stepSeconds.size(); ++k) out << k << "," << stepSeconds[k] << "\n";
  });
}

}  // namespace semslam
