#include "semslam/io/convert/DatasetConverters.h"

#include <algorithm>

#include "semslam/core/InputError.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam {

const std::vector<std::string>& datasetKinds() {
  static const std::vector<std::string> kinds = {"utias-lost-in-the-woods", "utias-starry-night", "mrclam", "isam",
                                                   "kitti-tracking"};
  return kinds;
}

namespace {

MeasurementLog convertKind(const std::string& kind, const std::string& path, const ConvertOptions& options,
                           ConversionStats* stats) {
  if (kind == "utias-lost-in-the-woods") return convertLostInTheWoods(path, options, stats);
  if (kind == "utias-starry-night") return convertStarryNight(path, options, stats);
  if (kind == "mrclam") return convertMrclam(path, options, stats);
  if (kind == "isam") return convertIsam(path, options, stats);
  return convertKittiTracking(path, options, stats);
}

}  // namespace

MeasurementLog convertDataset(const std::string& kind, const std::string& path, const ConvertOptions& options,
                              ConversionStats* stats) {
  if (std::find(datasetKinds().begin(), datasetKinds().end(), kind) != datasetKinds().end()) {
    MeasurementLog log = convertKind(kind, path, options, stats);
    // Numbers a dataset may hold but a log may not (a speed of 1e308 integrated into a pose): an input error
    // naming the dataset, not std::invalid_argument from the writer afterwards (`semslam convert` exited 1).
    checkMeasurementLog(log, path);
    return log;
  }
  std::string known;
  for (const std::string& name : datasetKinds()) known += (known.empty() ? "" : ", ") + name;
  throw InputError("unknown dataset kind '" + kind + "' (known: " + known + ")");
}

}  // namespace semslam
