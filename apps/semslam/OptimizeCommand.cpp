// semslam optimize FILE: batch optimisation of a pose graph (g2o, TORO or iSAM file), or, with --incremental, an
// online replay of it through the incremental smoother (io/PoseGraphReplay.h, solve/IncrementalSmoother.h).

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "Commands.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/core/InputError.h"
#include "semslam/io/PoseGraphAnchor.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/PoseGraphReplay.h"
#include "semslam/solve/IncrementalSmoother.h"
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
  bool incremental = false;
  bool finalConvergence = true;
  std::string stepTimes;
  IncrementalSmootherParams incrementalParams;
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

void writeReport(const OptimizeOptions& options, const nlohmann::json& report) {
  if (!options.report.empty()) {
    writeFileAtomically(options.report, [&report](std::ostream& out) { out << report.dump(2) << "\n"; });
    std::printf("wrote %s\n", options.report.c_str());
  }
}

void addMarginals(const std::vector<Key>& keys, const JointMarginal& joint, nlohmann::json& report) {
  nlohmann::json perKey = nlohmann::json::object();
  nlohmann::json keyNames = nlohmann::json::array();
  for (Key key : keys) {
    perKey[keyToString(key)] = matrixToJson(joint.at(key));
    keyNames.push_back(keyToString(key));
    std::printf("marginal covariance of %s:\n", keyToString(key).c_str());
    std::cout << joint.at(key) << "\n";
  }
  report["marginals"] = perKey;
  report["joint_marginal"] = {{"keys", keyNames}, {"matrix", matrixToJson(joint.covariance())}};
}

/// --incremental: each pose in key order with its edges to earlier poses (PoseGraphReplay), one update per pose,
/// the newest pose's estimate read after every update as an online front end would; then, unless disabled, one
/// Gauss-Newton convergence of the whole graph (IncrementalSmoother::convergeAll) so that final_chi2 is the optimum.
void runIncremental(const OptimizeOptions& options, const PoseGraphFile& file) {
  const PoseGraphReplay replay(file);
  IncrementalSmoother smoother(options.incrementalParams);
  std::vector<double> stepSeconds;
  stepSeconds.reserve(replay.size());
  double checksum = 0.0;  // keeps the newest-pose reads observable
  double reeliminated = 0.0;
  double relinearized = 0.0;
  double solved = 0.0;
  int fullReorderings = 0;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < replay.size(); ++k) {
    const auto stepStart = std::chrono::steady_clock::now();
    const ReplayStep step = replay.step(k, smoother.estimate());
    smoother.update(step.factors, step.values);
    checksum += dimension(smoother.estimate().value(step.pose));
    reeliminated += smoother.lastUpdate().reeliminatedVariables;
    relinearized += smoother.lastUpdate().relinearizedVariables;
    solved += smoother.lastUpdate().solvedCliques;
    fullReorderings += smoother.lastUpdate().fullReordering ? 1 : 0;
    stepSeconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count());
  }
  const double replaySeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  OptimizationResult convergence;
  double convergenceSeconds = 0.0;
  if (options.finalConvergence) {
    OptimizerParams params;
    params.maxIterations = options.maxIterations;
    const auto convergenceStart = std::chrono::steady_clock::now();
    convergence = smoother.convergeAll(params);
    convergenceSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - convergenceStart).count();
  }
  const double seconds = replaySeconds + convergenceSeconds;
  const auto worst = std::max_element(stepSeconds.begin(), stepSeconds.end());
  const std::size_t worstStep = static_cast<std::size_t>(worst - stepSeconds.begin());
  const double worstSeconds = stepSeconds.empty() ? 0.0 : *worst;
  const double initialChi2 = file.factors.chi2(file.initial);
  const double finalChi2 = file.factors.chi2(smoother.estimate());

  std::printf("%s: %zu variables, %zu edges, incremental replay of %zu steps (checksum %.0f)\n", options.file.c_str(),
              file.initial.size(), file.factors.size(), replay.size(), checksum);
  std::printf("replay %.4f s, worst step %.6f s (step %zu), final convergence %.4f s (%d iterations: %s)\n",
              replaySeconds, worstSeconds, worstStep, convergenceSeconds, convergence.iterations,
              options.finalConvergence ? convergence.stopReason.c_str() : "disabled");
  const double steps = std::max<double>(1.0, static_cast<double>(replay.size()));
  std::printf("per step: %.1f variables re-eliminated, %.1f relinearized, %.1f cliques solved; %d full reorderings\n",
              reeliminated / steps, relinearized / steps, solved / steps, fullReorderings);
  std::printf("final chi2 %.10g  time %.4f s\n", finalChi2, seconds);

  nlohmann::json report;
  report["file"] = options.file;
  report["format"] = options.format;
  report["solver"] = "incremental";
  report["variables"] = file.initial.size();
  report["edges"] = file.factors.size();
  report["steps"] = replay.size();
  report["initial_chi2"] = initialChi2;
  report["final_chi2"] = finalChi2;
  report["time_s"] = seconds;
  report["replay_time_s"] = replaySeconds;
  report["worst_step_time_s"] = worstSeconds;
  report["worst_step"] = worstStep;
  report["final_convergence"] = options.finalConvergence;
  report["final_convergence_time_s"] = convergenceSeconds;
  report["final_convergence_iterations"] = convergence.iterations;
  report["relinearize_threshold"] = options.incrementalParams.relinearizeThreshold;
  report["relinearize_skip"] = options.incrementalParams.relinearizeSkip;
  report["wildfire_threshold"] = options.incrementalParams.wildfireThreshold;
  report["mean_reeliminated_variables"] = reeliminated / steps;
  report["mean_relinearized_variables"] = relinearized / steps;
  report["mean_solved_cliques"] = solved / steps;
  report["full_reorderings"] = fullReorderings;
  report["cliques"] = smoother.cliqueCount();
  report["factor_entries"] = smoother.factorEntries();

  if (!options.marginals.empty()) {
    const std::vector<Key> keys = parseKeyList(options.marginals, file.initial);
    addMarginals(keys, smoother.jointMarginal(keys), report);
  }
  if (!options.stepTimes.empty()) {
    writeFileAtomically(options.stepTimes, [&](std::ostream& out) {
      out << "step,seconds\n";
      for (std::size_t k = 0; k < stepSeconds.size(); ++k) out << k << "," << stepSeconds[k] << "\n";
    });
    std::printf("wrote %s\n", options.stepTimes.c_str());
  }
  if (!options.out.empty()) {
    writeG2o(options.out, file.factors, smoother.estimate(), file.fixed);
    std::printf("wrote %s\n", options.out.c_str());
  }
  writeReport(options, report);
}

void run(const OptimizeOptions& options) {
  const PoseGraphFile file = readPoseGraph(options.file, parseGraphFormat(options.format));
  if (options.incremental) {
    runIncremental(options, file);
    return;
  }
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
    addMarginals(marginalKeys, marginals.jointMarginal(marginalKeys), report);
  }

  if (!options.out.empty()) {
    writeG2o(options.out, file.factors, result.values, file.fixed);
    std::printf("wrote %s\n", options.out.c_str());
  }
  writeReport(options, report);
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
  command->add_flag("--incremental", options->incremental,
                    "replay the graph pose by pose through the incremental smoother (iSAM2-style), reading the "
                    "newest pose after every update; report final_chi2, time_s and the worst step time");
  command->add_option("--relinearize-threshold", options->incrementalParams.relinearizeThreshold,
                      "--incremental: relinearize a variable whose update exceeds this (max-norm)")
      ->capture_default_str();
  command->add_option("--relinearize-skip", options->incrementalParams.relinearizeSkip,
                      "--incremental: check for relinearization every this many updates")
      ->capture_default_str();
  command->add_option("--wildfire-threshold", options->incrementalParams.wildfireThreshold,
                      "--incremental: partial state update threshold (0 solves every update exactly)")
      ->capture_default_str();
  command->add_flag("!--no-final-convergence", options->finalConvergence,
                    "--incremental: skip the final Gauss-Newton convergence of the whole graph");
  command->add_option("--step-times", options->stepTimes, "--incremental: write the time of every step as CSV");
  command->callback([options]() { run(*options); });
}

}  // namespace semslam::cli
