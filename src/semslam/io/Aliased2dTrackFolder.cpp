#include "semslam/io/Aliased2dTrackFolder.h"

#include <filesystem>

#include "semslam/core/InputError.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/StagedFolder.h"
#include "semslam/sim/Aliased2dSimulator.h"

namespace semslam {

std::string aliased2dTrackFileName(int track, int tracks) {
  int width = 3;
  for (int n = tracks - 1; n >= 1000; n /= 10) ++width;
  std::string digits = std::to_string(track);
  if (static_cast<int>(digits.size()) < width) digits.insert(0, static_cast<std::size_t>(width) - digits.size(), '0');
  return "track_" + digits + ".jsonl";
}

void writeAliased2dTrackFolder(const std::string& directory, const Aliased2dScenario& scenario, std::uint64_t seed,
                               int tracks, int steps, bool overwrite,
                               const std::function<void(int, int)>& progress) {
  namespace fs = std::filesystem;
  if (fs::exists(directory) && !fs::is_directory(directory)) {
    throw InputError("--out " + directory + ": is a file; with several tracks --out names a folder");
  }
  StagedFolder folder(directory, overwrite);
  for (int track = 0; track < tracks; ++track) {
    const MeasurementLog log = simulateAliased2dTrack(scenario, seed, track, steps, tracks);
    writeMeasurementLog((fs::path(folder.path()) / aliased2dTrackFileName(track, tracks)).string(), log);
    if (progress) progress(track + 1, tracks);
  }
  folder.commit();
}

}  // namespace semslam
