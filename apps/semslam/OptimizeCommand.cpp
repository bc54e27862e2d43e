// semslam optimize FILE: batch optimisation of a pose graph (g2o, TORO or iSAM file), or, with --incremental, an
// online replay of it through the incremental smoother (run/PoseGraphOptimization.h); prints a summary and writes
// the optimised graph, the JSON report and the step times on request (io/PoseGraphOptimizationReport.h).

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "Commands.h"
#include "semslam/core/ProgressBar.h"
#include "semslam/io/OutputTarget.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/PoseGraphOptimizationReport.h"
#include "semslam/run/PoseGraphOptimization.h"

namespace semslam::cli {

namespace {

struct OptimizeArguments {
  std::string solver = "gn";
  std::string out;
  std::string report;
  std::string stepTimes;
  bool quiet = false;
  PoseGraphOptimizationOptions options;
};

void printBatch(const PoseGraphOptimizationReport& report) {
  const OptimizationResult& result = report.result;
  std::printf("%s: %zu variables, %zu edges, %s\n", report.file.c_str(), report.variables, report.edges,
              report.solver == "lm" ? "Levenberg-Marquardt" : "Gauss-Newton");
  std::printf("initial chi2 %.10g  final chi2 %.10g  iterations %d  time %.4f s\n", report.initialChi2,
              report.finalChi2, result.iterations, report.seconds);
  std::printf("stopped: %s; max-norm of the gradient %.3e (initially %.3e)\n", result.stopReason.c_str(),
              result.finalGradientNorm, result.initialGradientNorm);
}

void printReplay(const PoseGraphOptimizationReport& report) {
  const PoseGraphReplayStatistics& replay = *report.replay;
  std::printf("%s: %zu variables, %zu edges, incremental replay of %zu steps (checksum %.0f)\n", report.file.c_str(),
              report.variables, report.edges, replay.steps, replay.checksum);
  std::printf("replay %.4f s, worst step %.6f s (step %zu), final convergence %.4f s (%d iterations: %s)\n",
              replay.replaySeconds, replay.worstStepSeconds, replay.worstStep, replay.finalConvergenceSeconds,
              report.result.iterations, replay.finalConvergence ? report.result.stopReason.c_str() : "disabled");
  std::printf("per step: %.1f variables re-eliminated, %.1f relinearized, %.1f cliques solved; %d full reorderings\n",
              replay.meanReeliminatedVariables, replay.meanRelinearizedVariables, replay.meanSolvedCliques,
              replay.fullReorderings);
  std::printf("final chi2 %.10g  time %.4f s\n", report.finalChi2, report.seconds);
}

void printMarginals(const JointMarginal& joint) {
  for (Key key : joint.keys()) {
    std::printf("marginal covariance of %s:\n", keyToString(key).c_str());
    std::cout << joint.at(key) << "\n";
  }
}

void run(OptimizeArguments arguments) {
  // Outputs are checked before the work: never an input, a link or a device (io/OutputTarget.h).
  for (const auto& [output, flag] : {std::pair{arguments.out, "--out"}, std::pair{arguments.report, "--report"},
                                     std::pair{arguments.stepTimes, "--step-times"}}) {
    if (output.empty()) continue;
    requireOutputSparesInput(output, arguments.options.file, flag);
    requireReplaceableFile(output);
  }
  arguments.options.solver = arguments.solver == "lm" ? SolverType::LevenbergMarquardt : SolverType::GaussNewton;
  // The incremental replay shows its progress per step (core/ProgressBar.h); the number of steps is known once
  // the file is read, at the first step.
  std::optional<ProgressBar> progress;
  arguments.options.progress = [&progress, quiet = arguments.quiet](int done, int total) {
    if (!progress) progress.emplace("optimize --incremental", total, quiet);
    progress->update(done);
  };
  const PoseGraphOptimizationReport report = optimizePoseGraphFile(arguments.options);
  if (report.replay) {
    printReplay(report);
  } else {
    printBatch(report);
  }
  if (report.marginals) printMarginals(*report.marginals);
  if (report.replay && !arguments.stepTimes.empty()) {
    writeReplayStepTimes(arguments.stepTimes, report.replay->stepSeconds);
    std::printf("wrote %s\n", arguments.stepTimes.c_str());
  }
  if (!arguments.out.empty()) {
    writeG2o(arguments.out, report.graph, report.estimate, report.fixed);
    std::printf("wrote %s\n", arguments.out.c_str());
  }
  if (!arguments.report.empty()) {
    writePoseGraphReport(arguments.report, report);
    std::printf("wrote %s\n", arguments.report.c_str());
  }
}

}  // namespace

void addOptimizeCommand(CLI::App& app) {
  auto arguments = std::make_shared<OptimizeArguments>();
  PoseGraphOptimizationOptions& options = arguments->options;
  CLI::App* command = app.add_subcommand("optimize", "Optimise a pose graph (g2o, TORO or iSAM file)");
  command->add_option("FILE", options.file, "pose-graph file")->required();
  command->add_option("--solver", arguments->solver, "gn (Gauss-Newton) or lm (Levenberg-Marquardt)")
      ->check(CLI::IsMember({"gn", "lm"}))
      ->capture_default_str();
  command->add_option("--format", options.format, "g2o, toro or isam (EDGE2 differs between the last two)")
      ->check(CLI::IsMember({"g2o", "toro", "isam"}))
      ->capture_default_str();
  command->add_option("--out", arguments->out, "write the optimised graph as g2o");
  command->add_option("--marginals", options.marginals,
                      "comma-separated ids whose marginal and joint covariance to report (x12,l3 for iSAM)");
  command->add_option("--report", arguments->report, "write a JSON report");
  command->add_option("--max-iterations", options.maxIterations, "iteration limit")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  command->add_flag("--verbose", options.verbose, "print every iteration");
  command->add_flag("--incremental", options.incremental,
                    "replay the graph pose by pose through the incremental smoother (iSAM2-style), reading the "
                    "newest pose after every update; report final_chi2, time_s and the worst step time");
  command->add_option("--relinearize-threshold", options.incrementalParams.relinearizeThreshold,
                      "--incremental: relinearize a variable whose update exceeds this (max-norm)")
      ->capture_default_str();
  command->add_option("--relinearize-skip", options.incrementalParams.relinearizeSkip,
                      "--incremental: check for relinearization every this many updates")
      ->capture_default_str();
  command->add_option("--wildfire-threshold", options.incrementalParams.wildfireThreshold,
                      "--incremental: partial state update threshold (0 solves every update exactly)")
      ->capture_default_str();
  command->add_flag("!--no-final-convergence", options.finalConvergence,
                    "--incremental: skip the final Gauss-Newton convergence of the whole graph");
  command->add_option("--step-times", arguments->stepTimes, "--incremental: write the time of every step as CSV");
  command->add_flag("--quiet", arguments->quiet, "--incremental: no progress line");
  command->callback([arguments]() { run(*arguments); });
}

}  // namespace semslam::cli
