#pragma once
// The subcommands of the `semslam` tool. Each lives in its own <Name>Command.cpp and registers itself on the
// top-level app; its callback throws semslam::InputError for bad input (exit 2) and anything else for failures
// (exit 1).

#include <CLI/CLI.hpp>

namespace semslam::cli {

void addOptimizeCommand(CLI::App& app);
void addDemoCommand(CLI::App& app);
void addEvalCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
void addSimulateCommand(CLI::App& app);
void addConvertCommand(CLI::App& app);
void addRunCommand(CLI::App& app);
void addStudyCommand(CLI::App& app);
/// Subcommands of `study` (StudyCommand.cpp).
void addStudyHybridCommand(CLI::App& study);
void addStudyRobustnessCommand(CLI::App& study);

}  // namespace semslam::cli
