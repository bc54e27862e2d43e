#include "semslam/io/convert/DatasetConverters.h"

#include <algorithm>

#include "semslam/core/InputError.h"

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
    // Every converter ends in finishConversion, which checks the log with the reader's rules: numbers a dataset may
    // hold but a log may not (a speed of 1e308 integrated into a pose) are an InputError at the row that made them.
    return convertKind(kind, path, options, stats);
  }
  std::string known;
  for (const std::string& name : datasetKinds()) known += (known.empty() ? "" : ", ") + name;
  throw InputError("unknown dataset kind '" + kind + "' (known: " + known + ")");
}

}  // namespace semslam
