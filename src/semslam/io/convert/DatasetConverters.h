#pragma once
// The dataset converters by name, as `semslam convert KIND PATH` names them:
//   utias-lost-in-the-woods  PATH = the dataset folder          (LostInTheWoodsConverter.h)
//   utias-starry-night       PATH = the dataset folder          (StarryNightConverter.h)
//   mrclam                   PATH = a MRCLAM_DatasetN folder     (MrclamConverter.h; ConvertOptions::robot)
//   isam                     PATH = a cityTrees10000-style file  (IsamConverter.h)
//   kitti-tracking           PATH = the kitti-tracking folder     (KittiTrackingConverter.h; ConvertOptions::kitti)
// docs/datasets.md describes each one's frames, units, noise values and decisions.

#include <string>
#include <vector>

#include "semslam/io/convert/ConvertOptions.h"
#include "semslam/io/convert/IsamConverter.h"
#include "semslam/io/convert/KittiTrackingConverter.h"
#include "semslam/io/convert/LostInTheWoodsConverter.h"
#include "semslam/io/convert/MrclamConverter.h"
#include "semslam/io/convert/StarryNightConverter.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// The kinds above, in that order.
const std::vector<std::string>& datasetKinds();

/// Converts the dataset at `path` with the converter `kind`; throws InputError for an unknown kind, and for a log
/// the measurement-log reader would refuse (numbers beyond its limits), at the dataset file and line that made the
/// refused part (io/convert/ConvertedLogCheck.h).
MeasurementLog convertDataset(const std::string& kind, const std::string& path, const ConvertOptions& options,
                              ConversionStats* stats = nullptr);

}  // namespace semslam
