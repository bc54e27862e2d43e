#pragma once
// The log of KITTI tracking's read-out configuration (docs/results.md, KITTI tracking section; issue 11): one
// sequence at 1 Hz keyframes with ORB-SLAM3's odometry plus seeded noise at scale 5, seed 1, as
// `semslam convert kitti-tracking DIR --sequence N --keyframe-period 1 --odometry noisy --odom-noise-scale 5
// --seed 1` writes it. Callers find the folder with SEMSLAM_REQUIRE_DATA (TestData.h).

#include <filesystem>

#include "semslam/io/convert/DatasetConverters.h"

namespace semslam::test {

inline MeasurementLog kittiTrackingReadoutLog(const std::filesystem::path& folder, int sequence) {
  ConvertOptions convert;
  convert.keyframePeriod = 1.0;
  convert.seed = 1;
  convert.kitti.sequence = sequence;
  convert.kitti.odometry = KittiTrackingOptions::Odometry::Noisy;
  convert.kitti.odometryNoiseScale = 5.0;
  return convertDataset("kitti-tracking", folder.string(), convert);
}

}  // namespace semslam::test
