#pragma once
// The converters' readers as fuzz harnesses (`semslam convert KIND`, io/convert/DatasetConverters.h): each input is
// a dataset folder packed into one file (fuzz/PackedFolder.h, "==> odometry.txt <==" sections), unpacked into a
// private folder, converted with fixed options (3 classes, 10 % misclassification, seed 1) and the log checked
// by the writer's own validation (writeMeasurementLog into the private folder), as `semslam convert` does. The
// contract: an InputError, or a log the writer accepts; anything else (a crash, std::invalid_argument from the
// writer, which `semslam convert` reports as exit 1) is a finding.

#include <map>
#include <set>
#include <string>

#include "PackedFolder.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/io/convert/DatasetConverters.h"

namespace semslam::fuzz {

/// The files a converter reads from its folder (the iSAM converter: the file g.txt and its ground truth beside it).
inline const std::set<std::string>& converterFiles(const std::string& kind) {
  static const std::map<std::string, std::set<std::string>> files = {
      {"isam", {"g.txt", "g_gt_poses_DERIVED.txt", "g_gt_landmarks_DERIVED.txt"}},
      {"utias-lost-in-the-woods",
       {"odometry.txt", "groundtruth.txt", "landmarks_groundtruth.txt", "measurements.txt", "params.txt"}},
      {"utias-starry-night",
       {"imu_velocities.txt", "groundtruth.txt", "landmarks_groundtruth.txt", "rbe_measurements_vehicle_frame.txt",
        "stereo_measurements.txt", "calibration.txt"}},
      {"mrclam",
       {"Barcodes.dat", "Landmark_Groundtruth.dat", "Robot1_Odometry.dat", "Robot1_Measurement.dat",
        "Robot1_Groundtruth.dat"}},
      {"kitti-tracking",
       {"orbslam3_stereo_poses/0000.txt", "label_02/0000.txt", "pointrcnn_detections/Car/0000.txt",
        "pointrcnn_detections/Pedestrian/0000.txt", "pointrcnn_detections/Cyclist/0000.txt"}},
  };
  return files.at(kind);
}

inline void convertPacked(const std::string& kind, const std::string& packedPath) {
  const PackedFolder folder(packedPath, converterFiles(kind));
  ConvertOptions options;
  options.classes = kind == "kitti-tracking" ? 1 : 3;  // kitti-tracking keeps the detector's three labels
  options.misclassification = kind == "kitti-tracking" ? 0.0 : 0.1;
  options.seed = 1;
  options.kitti.sequence = 0;
  const std::string path = kind == "isam" ? folder.path("g.txt") : folder.path();
  ConversionStats stats;
  const MeasurementLog log = convertDataset(kind, path, options, &stats);
  writeMeasurementLog(folder.path("converted.jsonl"), log);
}

}  // namespace semslam::fuzz
