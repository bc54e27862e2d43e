// semslam: SLAM with ambiguous data association, from the command line.

#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "Commands.h"
#include "semslam/core/InputError.h"
#include "semslam/core/Version.h"

int main(int argc, char** argv) {
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int printed = app.exit(error);  // prints help, or the usage error with a hint
    return printed == 0 ? 0 : 2;          // usage errors are bad input too
  } catch (const semslam::InputError& error) {
    std::cerr << "semslam: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "semslam: failed: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
