// semslam optimize FILE: batch optimisation of a pose graph (g2o, TORO or iSAM file).

#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "Commands.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/InputError.h"
#include "semslam/io/PoseGraphAnchor.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/Optimizer.h"

namespace semslam::cli {

namespace {

struct OptimizeOptions {
  std::string file;
  std::string solver = "gn";
  std::string format = "g2o";
  std::string out;
  std::string marginals;
  std::string report;
  int maxIterations = 100;
  bool verbose = false;
};

std::vector<Key> parseKeyList(const std::string& list, const Values& values) {
  std::vector<Key> keys;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    Key key = 0;
    try {
      key = keyFromString(item);
    } catch (const std::invalid_argument& error) {
      throw InputError("--marginals: " + std::string(error.what()));
    }
    if (!values.exists(key)) throw InputError("--marginals: the graph has no variable " + item);
    keys.push_back(key);
  }
  if (keys.empty()) throw InputError("--marginals: no ids given");
  return keys;
}

nlohmann::json matrixToJson(const Matrix& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

void run(const OptimizeOptions& options) {
  const PoseGraphFile file = readPoseGraph(options.file, parseGraphFormat(options.format));
  FactorGraph graph = file.factors;
  graph.add(anchorFactors(file));

  OptimizerParams params;
  params.solver = options.solver == "lm" ? SolverType::LevenbergMarquardt : SolverType::GaussNewton;
  params.maxIterations = options.maxIterations;
  params.verbose = options.verbose;
  std::vector<Key> marginalKeys;
  if (!options.marginals.empty()) marginalKeys = parseKeyList(options.marginals, file.initial);

  const auto start = std::chrono::steady_clock::now();
  const OptimizationResult result = optimize(graph, file.initial, params);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // chi2 over the file's own edges (the anchoring prior excluded).
  const double initialChi2 = file.factors.chi2(file.initial);
  const double finalChi2 = file.factors.chi2(result.values);
  std::printf("%s: %zu variables, %zu edges, %s\n", options.file.c_str(), file.initial.size(), file.factors.size(),
              options.solver == "lm" ? "Levenberg-Marquardt" : "Gauss-Newton");
  std::printf("initial chi2 %.10g  final chi2 %.10g  iterations %d  time %.4f s\n", initialChi2, finalChi2,
              result.iterations, seconds);
  std::printf("stopped: %s; max-norm of the gradient %.3e (initially %.3e)\n", result.stopReason.c_str(),
              result.finalGradientNorm, result.initialGradientNorm);

  nlohmann::json report;
  report["file"] = options.file;
  report["format"] = options.format;
  report["solver"] = options.solver;
  report["variables"] = file.initial.size();
  report["edges"] = file.factors.size();
  report["initial_chi2"] = initialChi2;
  report["final_chi2"] = finalChi2;
  report["iterations"] = result.iterations;
  report["time_s"] = seconds;
  report["converged"] = result.converged;
  report["stop_reason"] = result.stopReason;
  report["initial_gradient_norm"] = result.initialGradientNorm;
  report["final_gradient_norm"] = result.finalGradientNorm;

  if (!marginalKeys.empty()) {
    const Marginals marginals(graph, result.values);
    const JointMarginal joint = marginals.jointMarginal(marginalKeys);
    nlohmann::json perKey = nlohmann::json::object();
    nlohmann::json keyNames = nlohmann::json::array();
    for (Key key : marginalKeys) {
      perKey[keyToString(key)] = matrixToJson(joint.at(key));
      keyNames.push_back(keyToString(key));
      std::printf("marginal covariance of %s:\n", keyToString(key).c_str());
      std::cout << joint.at(key) << "\n";
    }
    report["marginals"] = perKey;
    report["joint_marginal"] = {{"keys", keyNames}, {"matrix", matrixToJson(joint.covariance())}};
  }

  if (!options.out.empty()) {
    writeG2o(options.out, file.factors, result.values, file.fixed);
    std::printf("wrote %s\n", options.out.c_str());
  }
  if (!options.report.empty()) {
    writeFileAtomically(options.report, [&report](std::ostream& out) { out << report.dump(2) << "\n"; });
    std::printf("wrote %s\n", options.report.c_str());
  }
}

}  // namespace

void addOptimizeCommand(CLI::App& app) {
  auto options = std::make_shared<OptimizeOptions>();
  CLI::App* command = app.add_subcommand("optimize", "Optimise a pose graph (g2o, TORO or iSAM file)");
  command->add_option("FILE", options->file, "pose-graph file")->required();
  command->add_option("--solver", options->solver, "gn (Gauss-Newton) or lm (Levenberg-Marquardt)")
      ->check(CLI::IsMember({"gn", "lm"}))
      ->capture_default_str();
  command->add_option("--format", options->format, "g2o, toro or isam (EDGE2 differs between the last two)")
      ->check(CLI::IsMember({"g2o", "toro", "isam"}))
      ->capture_default_str();
  command->add_option("--out", options->out, "write the optimised graph as g2o");
  command->add_option("--marginals", options->marginals,
                      "comma-separated ids whose marginal and joint covariance to report (x12,l3 for iSAM)");
  command->add_option("--report", options->report, "write a JSON report");
  command->add_option("--max-iterations", options->maxIterations, "iteration limit")->capture_default_str();
  command->add_flag("--verbose", options->verbose, "print every iteration");
  command->callback([options]() { run(*options); });
}

}  // namespace semslam::cli
