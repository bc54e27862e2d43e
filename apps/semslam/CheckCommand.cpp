// semslam check LOG: validates a measurement log (docs/measurement-log.md) and prints its summary
// (io/MeasurementLogSummary.h).

#include <cstdio>
#include <memory>
#include <string>

#include "Commands.h"
#include "semslam/io/MeasurementLogSummary.h"

namespace semslam::cli {

void addCheckCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto residuals = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand(
      "check", "Validate a measurement log (docs/measurement-log.md) and print its summary; exit 2 if it is bad");
  command->add_option("LOG", *path, "measurement log (JSON lines)")->required();
  command->add_flag("--residuals", *residuals,
                    "also print the residuals of detections and odometry against the log's ground truth");
  command->callback([path, residuals]() {
    std::fputs(formatMeasurementLogSummary(summarizeMeasurementLog(*path, *residuals)).c_str(), stdout);
  });
}

}  // namespace semslam::cli
