// semslam: SLAM with ambiguous data association, from the command line.

#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "Commands.h"
#include "OptionValidators.h"
#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/core/Version.h"
#include "semslam/io/InterruptCleanup.h"

int main(int argc, char** argv) {
  // SIGINT and SIGTERM remove every partial output and exit 130 / 143 (io/InterruptCleanup.h).
  semslam::installInterruptCleanup();
  CLI::App app{"semslam: SLAM with ambiguous data association (hybrid belief and semantic max-mixtures)"};
  // `semslam --version` prints "semslam 0.1.0" (the CMake project VERSION) and exits 0, with no subcommand.
  app.set_version_flag("--version", "semslam " + std::string(semslam::version()));
  app.require_subcommand(1);
  semslam::cli::addOptimizeCommand(app);
  semslam::cli::addDemoCommand(app);
  semslam::cli::addEvalCommand(app);
  semslam::cli::addCheckCommand(app);
  semslam::cli::addSimulateCommand(app);
  semslam::cli::addConvertCommand(app);
  semslam::cli::addRunCommand(app);
  semslam::cli::addStudyCommand(app);
  semslam::cli::requireDecimalIntegers(app);  // CLI11 reads "010" as octal eight
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version
    // A usage error (bad input too, exit 2). CLI11 quotes the value as given: bound and escape it.
    std::cerr << semslam::boundedMessage(error.what()) << "\nRun with --help for more information.\n";
    return 2;
  } catch (const semslam::InputError& error) {
    std::cerr << "semslam: error: " << semslam::boundedMessage(error.what()) << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "semslam: failed: " << semslam::boundedMessage(error.what()) << "\n";
    return 1;
  }
  return 0;
}
