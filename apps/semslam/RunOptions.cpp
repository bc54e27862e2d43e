#include "RunOptions.h"

#include <cstdint>
#include <stdexcept>

#include "MethodOptions.h"
#include "OptionValidators.h"
#include "semslam/core/InputError.h"
#include "semslam/run/KnownTrajectoryCeiling.h"
#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam::cli {

void addRunMethodOptions(CLI::App* command, RunMethodArguments& arguments) {
  command->add_option("--method", arguments.method, "known, ml, gpda, mm, mm-nh, hybrid or hybrid-geometric")
      ->check(CLI::IsMember(methodNames()))
      ->capture_default_str();
  command->add_option("--smoother", arguments.smoother,
                      "back end: incremental or batch (default: incremental for known..mm-nh, batch for hybrid)")
      ->check(CLI::IsMember({"incremental", "batch"}));
  command->add_option("--switch-rounds", arguments.options.switchRounds,
                      "mm, mm-nh, incremental back end: after an update, a max-mixture whose component at the new "
                      "estimate differs is relinearized there and the update solved again, up to this many times "
                      "(0: off; docs/association-front-end.md §6)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command
      ->add_option_function<double>(
          "--relinearize-threshold",
          [&arguments](double threshold) { arguments.options.relinearizeThreshold = threshold; },
          "paper B's methods, incremental back end: relinearize a variable whose update exceeds this (max-norm; "
          "default 0.05; slam/SemanticSlamSmoother.h)")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option_function<int>(
          "--relinearize-skip", [&arguments](int skip) { arguments.options.relinearizeSkip = skip; },
          "paper B's methods, incremental back end: check for relinearization every this many updates (default 1; "
          "slam/SemanticSlamSmoother.h, docs/association-front-end.md §10)")
      ->check(CLI::Range(1, 1000000));
  addSemanticSlamOptions(command, arguments.options.slam);
  command->add_flag("--no-covariances", arguments.noCovariances,
                    "skip the marginal covariance of every pose (no NEES, no ellipses; faster)");
  command->add_flag("--on-known-trajectory", arguments.onKnownTrajectory,
                    "paper B's methods: pin the poses to the known-association estimate (the association ceiling)");
  command->add_option("--pose-error-scale", arguments.poseErrorScale,
                      "with --on-known-trajectory: move the poses by a draw of s times their known-DA uncertainty "
                      "(--pose-error-draw)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--pose-error-draw", arguments.poseErrorDraw,
                      "with --pose-error-scale: joint (the trajectory from the known-DA posterior, errors correlated "
                      "as the estimate's) or independent (each pose from its own marginal)")
      ->check(CLI::IsMember({"joint", "independent"}))
      ->capture_default_str();
  command->add_flag("--on-true-history", arguments.onTrueHistory,
                    "paper B's methods but known: the graph holds the true associations and the front end's own "
                    "decision on each detection is scored, never applied (docs/association-front-end.md §8b)");
  command->add_option("--seed", arguments.options.hybrid.seed,
                      "hybrid: seed of the Monte Carlo draws; --pose-error-scale: seed of the pose errors")
      ->check(unsignedInteger64())
      ->capture_default_str();
  addHybridOptions(command, arguments.options.hybrid);
}

MethodRun runFromArguments(const MeasurementLog& log, RunMethodArguments arguments, const std::string& source,
                           const RunProgress& progress) {
  MethodOptions& options = arguments.options;
  options.method = parseMethod(arguments.method);
  if (!arguments.smoother.empty()) options.smoother = parseSmootherKind(arguments.smoother);
  options.poseCovariances = !arguments.noCovariances;
  options.slam.decideOnTrueHistory = arguments.onTrueHistory;
  try {
    if (arguments.onKnownTrajectory && arguments.onTrueHistory) {
      throw std::invalid_argument("--on-known-trajectory and --on-true-history are two ceilings: choose one");
    }
    if (arguments.onKnownTrajectory) {
      const PoseErrorDraw draw =
          arguments.poseErrorDraw == "independent" ? PoseErrorDraw::Independent : PoseErrorDraw::Joint;
      return runOnKnownTrajectory(log, options, arguments.poseErrorScale,
                                  static_cast<std::uint32_t>(options.hybrid.seed), draw);
    }
    return runMethod(log, options, progress);
  } catch (const std::invalid_argument& error) {
    throw InputError(source, 0, error.what());
  } catch (const std::domain_error& error) {  // a geometry the models cannot take (a point at its sensor)
    throw InputError(source, 0, error.what());
  } catch (const UnconstrainedSystemError& error) {  // the log leaves a variable free: say what would hold it
    throw InputError(source, 0,
                     std::string(error.what()) +
                         " (In a measurement log the header's initial_pose is the prior on the first pose and "
                         "landmark_priors hold known landmarks; docs/measurement-log.md.)");
  }
}

}  // namespace semslam::cli
