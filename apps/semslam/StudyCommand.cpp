// semslam study hybrid|robustness: the two papers' statistical studies, each in its own file
// (StudyHybridCommand.cpp: paper A on aliased2d; StudyRobustnessCommand.cpp: paper B's robustness sweeps).

#include "Commands.h"

namespace semslam::cli {

void addStudyCommand(CLI::App& app) {
  CLI::App* study = app.add_subcommand("study", "statistical studies over many seeded runs");
  study->require_subcommand(1);
  addStudyHybridCommand(*study);
  addStudyRobustnessCommand(*study);
}

}  // namespace semslam::cli
